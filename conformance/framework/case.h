// A conformance case and what it reports (docs/design.md, "Three oracles, one report").
//
// A case runs one scene through gpu/, emulation/ and reference/ and hands back, per oracle, a
// verdict with its figures; the runner (runner.h) turns results into results.json, junit.xml
// and index.html. Case ids are dotted lower_snake, most general first.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace voxref::conf {

class CaseContext;

enum class Status { Pass, Warn, Fail, Skip, Crash, Timeout };
std::string_view name(Status s);
std::optional<Status> parseStatus(std::string_view s);  // nullopt for an unknown name

// Per oracle. NotRun carries its reason in `summary` (for example GL could not run the case).
enum class Verdict { Pass, Warn, Fail, NotRun, Info };
std::string_view name(Verdict v);
std::optional<Verdict> parseVerdict(std::string_view s);

// What judged the GL output of a case: an oracle that held GL's output against something and could
// have failed it on this driver. An oracle of the emulation or the CPU alone, an informational
// one, and an envelope whose allowed interval spans the values that matter (blind) judge nothing.
enum class Judge {
  None,
  Exact,        // GL == the emulation under the driver's (calibrated or probed) profile, bit for bit
  Envelope,     // GL inside what any conforming implementation may produce
  Fetch,        // the texels GL's decoder fetched, against the exact addresses
  IsoGeometry,  // GL's isosurface images and occlusion queries against the Embree ground truth
  Prediction,   // GL's output against a paper's prediction (Fig. 9's clamping failure)
  GlBehaviour,  // GL's behaviour itself (a texture it must refuse)
};
std::string_view name(Judge j);  // "none", "exact", "envelope", "fetch", "iso_geometry", "prediction", "gl_behaviour"
std::optional<Judge> parseJudge(std::string_view s);
// Strongest first; a case's judgedBy is the first of these that one of its oracles judges.
inline constexpr Judge kJudges[] = {Judge::Exact,      Judge::Envelope,    Judge::Fetch, Judge::IsoGeometry,
                                    Judge::Prediction, Judge::GlBehaviour, Judge::None};

struct OracleResult {
  std::string oracle;  // "exact", "envelope", "ideal"
  Verdict verdict = Verdict::NotRun;
  std::string summary;
  nlohmann::json figures = nlohmann::json::object();
  Judge judges = Judge::None;  // what it judged of the GL output (Judge::None: nothing)
};

// Where a driver departs from the GL semantics, found by comparing it with a model of those
// semantics (emulation/profile.h, Departure). Findings inform; they never change a verdict.
struct Finding {
  std::string id;
  std::string description;
  nlohmann::json figures = nlohmann::json::object();
};

// One sample a case singles out for the report's magnified view: where it is (pixel x, y with
// row 0 at the bottom as GL reads back, and the plane or frame k), what the GL, emulated and
// reference paths hold there (NaN where a path has no value), and, when an envelope judged it,
// the interval it allows. Cases list their worst samples first, at most kMaxWorstPixels.
struct PixelValues {
  int x = 0, y = 0, k = 0;
  std::string oracle;  // the oracle that singled it out ("exact", "envelope", ...)
  double gl = 0.0, emulated = 0.0, reference = 0.0;
  std::optional<std::pair<double, double>> allowed;
};
inline constexpr std::size_t kMaxWorstPixels = 16;

struct CaseImages {  // paths relative to the report directory; empty when not written
  std::string rendered, emulated, reference, errorMask;
};

struct CaseResult {
  std::string id, system, description;
  Status status = Status::Pass;
  std::string message;           // reason of a skip, crash or failure
  Judge judgedBy = Judge::None;  // the oracle that carried the verdict on GL (concludeFromOracles)
  // The exact oracle failed against a profile the probe built (markProbedModelFailure): the probed
  // model does not hold here, which is not a regression against a calibrated profile.
  bool probedModelFailed = false;
  std::string stderrText;  // what the case's process wrote to stdout and stderr (kept for crashes and timeouts)
  std::vector<OracleResult> oracles;
  std::vector<std::string> effects;  // emulation/effects.h ids the emulator simulated
  std::vector<Finding> findings;
  // The case's own numbers (grids, passes ...): deterministic, compared between runs.
  nlohmann::json figures = nlohmann::json::object();
  double secondsGl = 0.0, secondsEmulation = 0.0, secondsReference = 0.0;
  // Other wall-clock times the case measured (seconds): kept apart from the figures, which must be
  // equal bit for bit between equal runs; never compared between runs.
  nlohmann::json timings = nlohmann::json::object();
  // Set by the runner: the wall time of the case (its process, from fork to end), the statuses of
  // its reruns (a flake check, expectations/outcomes.h), and its outcome against the run's
  // expectation files in deqp-runner's words ("Pass", "ExpectedFail", "Flake" ...).
  double seconds = 0.0;
  std::vector<Status> reruns;
  std::string outcome;
  CaseImages images;
  std::vector<PixelValues> worstPixels;
};

// Fail if any oracle failed, else warn if any warned, else pass; NotRun and Info do not count.
Status statusFromOracles(const std::vector<OracleResult>& oracles);

// Every judge ends with this: sets result.status from its oracles (statusFromOracles) and
// result.message to the one-line reason of a case that is not a pass, "<oracle>: <summary>" of the
// first oracle that failed, else of the first that warned; empty for a pass. A case that is not a
// pass always states its reason in one line (results.json, junit.xml, the terminal, index.html).
// result.judgedBy is the strongest oracle that judged the GL output (kJudges order). A case only
// passes (or warns) on such an oracle: where none judged, it is a skip, "not judged on this
// driver: " and why each oracle that could have judged did not (never a pass).
void concludeFromOracles(CaseResult& result);

// For a run judged against a probed profile: a case whose exact oracle failed is marked, and its
// message says "the probed model does not hold here: " before the oracle's reason.
void markProbedModelFailure(CaseResult& result);

struct Case {
  std::string id;
  std::string system;  // "sparsegrid", ...
  std::string description;
  std::function<CaseResult(CaseContext&)> run;
  // The case's scene (JSON), when it renders one: `voxref render --scene <case id>` uses it.
  std::optional<nlohmann::json> scene;
};

}  // namespace voxref::conf
