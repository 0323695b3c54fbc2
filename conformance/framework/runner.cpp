#include "conformance/framework/runner.h"
#include "conformance/framework/selection.h"

#include <algorithm>
#include <csignal>
#include <cstring>
#include <functional>
#include <map>
#include <ostream>
#include <regex>

#include "conformance/framework/case_context.h"
#include "conformance/framework/driver_info.h"
#include "conformance/framework/expectations/expectation_files.h"
#include "conformance/framework/expectations/outcomes.h"
#include "conformance/framework/isolation/child_processes.h"
#include "conformance/framework/isolation/interrupt.h"
#include "conformance/framework/probe/probed_profile.h"
#include "conformance/framework/probe/profile_choice.h"
#include "conformance/framework/progress.h"
#include "conformance/framework/report/baseline_diff.h"
#include "conformance/framework/report/judgement_counts.h"
#include "conformance/framework/report/report_files.h"
#include "conformance/framework/report/results_json.h"
#include "conformance/framework/report/results_reader.h"
#include "conformance/framework/run_selection.h"
#include "conformance/framework/run_summary.h"
#include "conformance/framework/stopwatch.h"
#include "conformance/io/atomic_file.h"
#include "gpu/gl_error.h"

namespace voxref::conf {
namespace {

// The driver's identity and the profile, as a child process learns them.
struct Identity {
  nlohmann::json driver;
  const emu::PrecisionProfile* profile = nullptr;  // nullptr: none (envelope oracle alone)
  std::string renderer, version;
};

// In this process: creates a context and chooses the profile (probe/profile_choice.h; the probe
// renders on this context where it runs). Throws gpu::GlUnavailable or UsageError (unknown
// profile, a driver.json the driver no longer probes as).
nlohmann::json identifyHere(const RunOptions& options) {
  std::unique_ptr<gpu::Context> gl = gpu::createContext(options.driver);
  const ProfileChoice choice = chooseRunProfile(options.profile, *gl);
  nlohmann::json driver = driverJson(gl->info(), choice.profile, choice.how);
  if (!choice.probe.is_null()) driver["probe"] = choice.probe;
  // The whole profile travels to the parent (a probed one exists only in this process).
  return {{"driver", driver},
          {"profile", choice.profile ? profileToJson(*choice.profile) : nlohmann::json(nullptr)},
          {"renderer", gl->info().renderer},
          {"version", gl->info().version}};
}

Identity toIdentity(const nlohmann::json& j) {
  const nlohmann::json& p = j.at("profile");
  const emu::PrecisionProfile* profile = nullptr;
  if (!p.is_null()) {
    const emu::PrecisionProfile* known =
        p.at("probed").get<bool>() ? nullptr : emu::findProfile(p.at("name").get<std::string>());
    profile = known ? known : &profileFromJson(p);
  }
  return {j.at("driver"), profile, j.at("renderer").get<std::string>(), j.at("version").get<std::string>()};
}

// Learns the identity in a child, so that the parent never holds a GL context (or its threads)
// when it forks the cases' processes; a driver that crashes while creating a context is reported
// as unavailable, with what it wrote.
Identity identify(const RunOptions& options) {
  if (options.inProcess) return toIdentity(identifyHere(options));
  nlohmann::json answer;
  isolation::ChildOutcome outcome;
  isolation::PoolOptions one;
  one.timeLimitSeconds = options.timeLimitSeconds;
  isolation::runEachInChild(
      1, one,
      [&](std::size_t) -> std::string {
        try {
          return nlohmann::json{{"ok", true}, {"identity", identifyHere(options)}}.dump();
        } catch (const UsageError& e) {
          return nlohmann::json{{"ok", false}, {"usage", true}, {"error", e.what()}}.dump();
        } catch (const std::exception& e) {
          return nlohmann::json{{"ok", false}, {"usage", false}, {"error", e.what()}}.dump();
        }
      },
      [&](std::size_t, const isolation::ChildOutcome& o) { outcome = o; });
  if (outcome.ending != isolation::Ending::Finished)
    throw gpu::GlUnavailable("creating the context: " + isolation::describe(outcome, options.timeLimitSeconds) +
                             (outcome.output.empty() ? "" : "; it wrote:\n" + outcome.output));
  answer = nlohmann::json::parse(outcome.result);
  if (!answer.at("ok").get<bool>()) {
    const std::string error = answer.at("error").get<std::string>();
    if (answer.at("usage").get<bool>()) throw UsageError(error);
    throw gpu::GlUnavailable(error);
  }
  return toIdentity(answer.at("identity"));
}

// The context a case runs with, under the profile identify() chose.
std::unique_ptr<CaseContext> makeCaseContext(const RunOptions& options, const Identity& identity, gpu::Context* gl) {
  return std::make_unique<CaseContext>(gl, identity.profile, options.outDir, options.threads, options.allImages,
                                       envelopeArithmetic(identity.driver.value("probe", nlohmann::json())));
}

// What a case's process wrote, as the report keeps it.
std::string keptOutput(const isolation::ChildOutcome& o) {
  return (o.outputTruncated ? "[... earlier output dropped]\n" : "") + o.output;
}

// The result of a case whose process did not hand one back.
CaseResult lostCase(const Case& c, const isolation::ChildOutcome& o, double timeLimit) {
  CaseResult r;
  r.id = c.id;
  r.system = c.system;
  r.description = c.description;
  r.status = o.ending == isolation::Ending::TimedOut ? Status::Timeout : Status::Crash;
  r.message = isolation::describe(o, timeLimit);
  r.stderrText = keptOutput(o);
  return r;
}

// The results so far in catalogue order, and the ids of the cases without one.
void collect(const std::vector<std::optional<CaseResult>>& slots, const std::vector<Case>& cases,
             std::vector<CaseResult>& results, std::vector<std::string>& notRun) {
  results.clear();
  notRun.clear();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (slots[i])
      results.push_back(*slots[i]);
    else
      notRun.push_back(cases[i].id);
  }
}

// Runs chosen cases of the run, each in its own process (or in this one, --in-process), and hands
// each result to the parent as it ends. While children run, results.json holds a snapshot
// (marked running and incomplete), refreshed at most every two seconds after markDirty(): a
// parent killed outright still leaves what ran.
class CaseRunner {
 public:
  CaseRunner(const RunOptions& options, const Identity& identity, const std::vector<Case>& cases,
             const std::vector<std::optional<CaseResult>>& slots, const RunInfo& run)
      : options_(options), identity_(identity), cases_(cases), slots_(slots), run_(run) {}

  void markDirty() { dirty_ = true; }

  // False when the run was interrupted (the cases not yet ended have no result).
  bool run(const std::vector<std::size_t>& which, const std::function<void(std::size_t, CaseResult)>& done) {
    if (options_.inProcess) {
      if (!gl_) gl_ = gpu::createContext(options_.driver);
      const std::unique_ptr<CaseContext> ctx = makeCaseContext(options_, identity_, gl_.get());
      for (std::size_t i : which) {
        const Clock::time_point t0 = Clock::now();
        CaseResult r = runCase(cases_[i], *ctx);
        r.seconds = secondsSince(t0);
        done(i, std::move(r));
      }
      return true;
    }
    isolation::PoolOptions pool;
    pool.jobs = options_.jobs;
    pool.timeLimitSeconds = options_.timeLimitSeconds;
    pool.tickSeconds = 2.0;
    pool.tick = [this] { snapshot(); };
    isolation::InterruptGuard guard;
    return isolation::runEachInChild(
        which.size(), pool,
        [&](std::size_t k) -> std::string {
          std::unique_ptr<gpu::Context> gl = gpu::createContext(options_.driver);
          const std::unique_ptr<CaseContext> ctx = makeCaseContext(options_, identity_, gl.get());
          return caseJson(runCase(cases_[which[k]], *ctx)).dump();
        },
        [&](std::size_t k, const isolation::ChildOutcome& o) {
          if (o.ending == isolation::Ending::Interrupted) return;  // not run: listed as such
          done(which[k], resultOf(cases_[which[k]], o));
        });
  }

 private:
  CaseResult resultOf(const Case& c, const isolation::ChildOutcome& o) const {
    CaseResult r;
    if (o.ending == isolation::Ending::Finished) {
      try {
        r = caseFromJson(nlohmann::json::parse(o.result));
        r.stderrText = keptOutput(o);
      } catch (const std::exception& e) {
        isolation::ChildOutcome bad = o;
        bad.ending = isolation::Ending::Exited;
        r = lostCase(c, bad, options_.timeLimitSeconds);
        r.message = std::string("the case's process handed back an unreadable result: ") + e.what();
      }
    } else {
      r = lostCase(c, o, options_.timeLimitSeconds);
    }
    r.seconds = o.seconds;
    return r;
  }

  void snapshot() {
    if (!dirty_) return;
    RunInfo now = run_;
    now.running = true;
    now.complete = false;
    std::vector<CaseResult> results;
    collect(slots_, cases_, results, now.notRun);
    io::writeFileAtomically(options_.outDir / "results.json", resultsText(now, results));
    dirty_ = false;
  }

  const RunOptions& options_;
  const Identity& identity_;
  const std::vector<Case>& cases_;
  const std::vector<std::optional<CaseResult>>& slots_;
  const RunInfo& run_;
  std::unique_ptr<gpu::Context> gl_;  // --in-process only
  bool dirty_ = false;
};

}  // namespace

CaseResult runCase(const Case& c, CaseContext& ctx) {
  CaseResult r;
  try {
    r = c.run(ctx);
  } catch (const gpu::GlUnsupported& e) {
    r.status = Status::Skip;
    r.message = e.what();
  } catch (const std::exception& e) {
    r.status = Status::Crash;
    r.message = std::string("the case threw: ") + e.what();
  }
  r.id = c.id;
  r.system = c.system;
  if (r.description.empty()) r.description = c.description;
  return r;
}

namespace {

// The run's expectation files and case lists, read before anything runs.
struct RunFiles {
  Expectations expectations;
  std::vector<ListedCase> caseList;
};

RunFiles readRunFiles(const RunOptions& o) {
  try {
    return {readExpectations(o.failsFiles, o.flakesFiles, o.skipsFiles), readCaseLists(o.caseLists)};
  } catch (const ExpectationFileError& e) {
    throw UsageError(e.what());
  }
}

std::regex checkRegex(const std::string& text, const char* option) {
  try {
    return std::regex(text, std::regex::ECMAScript);
  } catch (const std::regex_error& e) {
    throw UsageError(std::string(option) + " '" + text + "' is not a regular expression (" + e.what() + ")");
  }
}

// --renderer-check and --version-check, against what the identity child saw.
void checkDriver(const RunOptions& o, const Identity& identity) {
  auto check = [](const std::string& pattern, const char* option, const char* what, const std::string& actual) {
    if (pattern.empty() || std::regex_search(actual, checkRegex(pattern, option))) return;
    throw DriverCheckError(std::string(option) + " '" + pattern + "' does not match the " + what + " '" + actual +
                           "'; no case ran (is the job on the machine and driver it was written for?)");
  };
  check(o.rendererCheck, "--renderer-check", "renderer", identity.renderer);
  check(o.versionCheck, "--version-check", "version", identity.version);
}

nlohmann::json pathsJson(const std::vector<std::filesystem::path>& paths) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& p : paths) a.push_back(p.string());
  return a;
}

}  // namespace

RunOutcome runConformance(const RunOptions& options, const std::vector<Case>& catalogue, std::ostream& out) {
  if (options.jobs < 1) throw UsageError("--jobs must be at least 1");
  if (options.flakeReruns < 0) throw UsageError("--flake-reruns must be 0 or more");
  if (options.fraction < 1) throw UsageError("--fraction must be at least 1");
  checkRegex(options.rendererCheck, "--renderer-check");
  checkRegex(options.versionCheck, "--version-check");
  const RunFiles files = readRunFiles(options);
  const Expectations& expectations = files.expectations;
  const std::string& prefix = options.junit.idPrefix;
  SelectionRequest request;
  request.filter = options.filter;
  request.caseList = files.caseList;
  request.skips = &expectations.skips;
  request.idPrefix = prefix;
  request.fraction = options.fraction;
  request.shard = options.shard;
  const Selection selection = selectRun(catalogue, request);
  const std::vector<Case>& cases = selection.cases;

  std::vector<CaseResult> baseline;
  if (!options.baseline.empty()) {
    try {
      baseline = loadResults(options.baseline).cases;
    } catch (const ResultsFormatError& e) {
      throw UsageError("--baseline: " + std::string(e.what()));
    }
  }
  const Identity identity = identify(options);
  checkDriver(options, identity);
  // The identity child has loaded the driver's library and made a context with it: now the parent
  // loads the library too (no context, no thread), so that every case process forked from it
  // starts without loading and binding it again. A failure here changes nothing: each case's
  // process loads it as before and reports what it meets.
  if (!options.inProcess) try {
      gpu::preloadDriverLibrary(options.driver);
    } catch (const gpu::GlUnavailable&) {
    }
  io::ensureDirectory(options.outDir);

  RunInfo run;
  run.command = options.command;
  run.started = utcTimestamp();
  run.driver = identity.driver;
  run.execution = {{"isolation", options.inProcess ? "none (--in-process)" : "one process per case"},
                   {"jobs", options.inProcess ? 1 : options.jobs},
                   {"time_limit_seconds", options.inProcess ? 0.0 : options.timeLimitSeconds},
                   {"matched", selection.matched},
                   {"skipped_by_skips_files", selection.skipped},
                   {"fraction", options.fraction},
                   {"selected", selection.selected},
                   {"shard", options.shard ? nlohmann::json{{"index", options.shard->index},
                                                            {"count", options.shard->count},
                                                            {"cases", cases.size()},
                                                            {"from", options.shardFrom}}
                                           : nlohmann::json(nullptr)},
                   {"flake_reruns", options.flakeReruns},
                   {"id_prefix", prefix},
                   {"case_lists", pathsJson(options.caseLists)},
                   {"expectations",
                    {{"fails", pathsJson(options.failsFiles)},
                     {"flakes", pathsJson(options.flakesFiles)},
                     {"skips", pathsJson(options.skipsFiles)}}},
                   {"checks", {{"renderer", options.rendererCheck}, {"version", options.versionCheck}}}};
  out << "voxref conform: " << cases.size() << " case(s)";
  if (options.shard)
    out << " (shard " << options.shard->index << "/" << options.shard->count << " of " << selection.selected << ")";
  if (selection.skipped) out << ", " << selection.skipped << " removed by the skips file(s)";
  out << " on " << identity.renderer << " (" << identity.version << ") through "
      << identity.driver.value("api", std::string("?")) << ", profile "
      << (identity.profile ? std::string(identity.profile->name) + (identity.profile->probed ? " (probed)" : "")
                           : std::string("none: envelope oracle alone"))
      << ", "
      << (options.inProcess ? std::string("in this process") : std::to_string(options.jobs) + " process(es) at once")
      << std::endl;
  // What a rerun must set to get the same driver (gpu::environmentPins; all of it is in results.json).
  std::string set;
  const nlohmann::json environment = identity.driver.value("environment", nlohmann::json::object());
  for (const auto& [k, v] : environment.items())
    if (v.is_string() && v != "(unset)") set += " " + k + "=" + v.get<std::string>();
  if (!set.empty()) out << "environment:" << set << std::endl;
  if (const nlohmann::json& p = identity.driver.value("profile", nlohmann::json::object()); p.contains("chosen"))
    out << "profile: " << p.at("chosen").get<std::string>() << std::endl;

  std::vector<std::optional<CaseResult>> slots(cases.size());
  CaseRunner runner(options, identity, cases, slots, run);
  Progress progress("voxref conform", static_cast<long>(cases.size()));
  long done = 0;
  std::vector<std::size_t> all(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) all[i] = i;
  bool complete = runner.run(all, [&](std::size_t i, CaseResult r) {
    slots[i] = std::move(r);
    runner.markDirty();
    progress.update(++done, cases[i].id);
  });
  progress.finish();

  // Flakes: a case that failed unexpectedly runs again, in a fresh process, up to flakeReruns times;
  // a pass on one makes it a Flake (expectations/outcomes.h).
  for (int round = 1; complete && round <= options.flakeReruns; ++round) {
    std::vector<std::size_t> again;
    for (std::size_t i = 0; i < cases.size(); ++i)
      if (slots[i] && wantsRerun(prefix + slots[i]->id, *slots[i], expectations) &&
          std::none_of(slots[i]->reruns.begin(), slots[i]->reruns.end(),
                       [](Status s) { return s == Status::Pass || s == Status::Warn; }))
        again.push_back(i);
    if (again.empty()) break;
    out << "rerunning " << again.size() << " case(s) that failed unexpectedly, to tell a flake (rerun " << round
        << " of " << options.flakeReruns << ")" << std::endl;
    complete = runner.run(again, [&](std::size_t i, const CaseResult& r) { slots[i]->reruns.push_back(r.status); });
  }
  if (!complete)
    run.interruptedBy = std::string("SIG") +
                        (sigabbrev_np(isolation::interruptSignal()) ? sigabbrev_np(isolation::interruptSignal()) : "?");

  RunOutcome outcome;
  outcome.complete = complete;
  collect(slots, cases, outcome.results, run.notRun);
  bool jobFails = false;
  for (CaseResult& r : outcome.results) {
    if (identity.profile && identity.profile->probed) markProbedModelFailure(r);
    const Outcome o = classify(prefix + r.id, &r, r.reruns, expectations);
    r.outcome = outcomeName(o, r.status);
    jobFails = jobFails || failsJob(o);
  }
  run.complete = complete;
  run.finished = utcTimestamp();
  BaselineDiff diff;
  if (!options.baseline.empty()) {
    diff = compareWithBaseline(baseline, outcome.results);
    run.baseline = baselineJson(diff, options.baseline.string());
  }
  writeReportFiles(options.outDir, run, outcome.results, options.junit);

  printRunSummary(out, outcome.results, options.slowest);
  if (!options.baseline.empty()) printBaselineDiff(out, diff, options.baseline.string());
  if (!complete)
    out << "INTERRUPTED by " << run.interruptedBy << ": partial report, " << outcome.results.size() << " of "
        << cases.size() << " case(s) ran, " << run.notRun.size() << " not run\n";
  out << "report: " << (options.outDir / "index.html").string()
      << " (results.json, junit.xml, results.csv, failures.csv beside it)\n";
  outcome.exitCode = !complete          ? 128 + isolation::interruptSignal()
                     : diff.regressed() ? kExitRegressed
                     : jobFails         ? kExitFailed
                                        : kExitPass;
  return outcome;
}

}  // namespace voxref::conf
