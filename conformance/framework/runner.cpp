#include "conformance/framework/runner.h"
#include "conformance/framework/selection.h"

#include <csignal>
#include <cstring>
#include <map>
#include <ostream>

#include "conformance/framework/case_context.h"
#include "conformance/framework/driver_info.h"
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
  return std::make_unique<CaseContext>(gl, identity.profile, options.outDir, options.threads, options.allImages);
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

RunOutcome runConformance(const RunOptions& options, const std::vector<Case>& catalogue, std::ostream& out) {
  std::vector<Case> cases = selectCases(catalogue, options.filter);
  if (cases.empty()) throw UsageError("no case matches '" + options.filter + "' (voxref list shows them)");
  const std::size_t selected = cases.size();
  if (options.shard) cases = shardOf(cases, *options.shard);
  if (options.jobs < 1) throw UsageError("--jobs must be at least 1");

  std::vector<CaseResult> baseline;
  if (!options.baseline.empty()) {
    try {
      baseline = loadResults(options.baseline).cases;
    } catch (const ResultsFormatError& e) {
      throw UsageError("--baseline: " + std::string(e.what()));
    }
  }
  const Identity identity = identify(options);
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
                   {"selected", selected},
                   {"shard", options.shard ? nlohmann::json{{"index", options.shard->index},
                                                            {"count", options.shard->count},
                                                            {"cases", cases.size()}}
                                           : nlohmann::json(nullptr)}};
  out << "voxref conform: " << cases.size() << " case(s)";
  if (options.shard)
    out << " (shard " << options.shard->index << "/" << options.shard->count << " of " << selected << ")";
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
  Progress progress("voxref conform", static_cast<long>(cases.size()));
  long done = 0;
  bool complete = true;
  if (options.inProcess) {
    std::unique_ptr<gpu::Context> gl = gpu::createContext(options.driver);
    const std::unique_ptr<CaseContext> ctx = makeCaseContext(options, identity, gl.get());
    for (std::size_t i = 0; i < cases.size(); ++i) {
      progress.update(done, cases[i].id);
      slots[i] = runCase(cases[i], *ctx);
      ++done;
    }
  } else {
    // While the run goes on, results.json holds a snapshot (marked running and incomplete),
    // refreshed at most every two seconds: a parent killed outright still leaves what ran.
    bool dirty = false;
    auto snapshot = [&] {
      if (!dirty) return;
      RunInfo now = run;
      now.running = true;
      now.complete = false;
      std::vector<CaseResult> results;
      collect(slots, cases, results, now.notRun);
      io::writeFileAtomically(options.outDir / "results.json", resultsText(now, results));
      dirty = false;
    };
    isolation::PoolOptions pool;
    pool.jobs = options.jobs;
    pool.timeLimitSeconds = options.timeLimitSeconds;
    pool.tickSeconds = 2.0;
    pool.tick = snapshot;
    isolation::InterruptGuard guard;
    complete = isolation::runEachInChild(
        cases.size(), pool,
        [&](std::size_t i) -> std::string {
          std::unique_ptr<gpu::Context> gl = gpu::createContext(options.driver);
          const std::unique_ptr<CaseContext> ctx = makeCaseContext(options, identity, gl.get());
          return caseJson(runCase(cases[i], *ctx)).dump();
        },
        [&](std::size_t i, const isolation::ChildOutcome& o) {
          if (o.ending == isolation::Ending::Interrupted) return;  // not run: listed as such
          if (o.ending == isolation::Ending::Finished) {
            try {
              CaseResult r = caseFromJson(nlohmann::json::parse(o.result));
              r.stderrText = keptOutput(o);
              slots[i] = std::move(r);
            } catch (const std::exception& e) {
              isolation::ChildOutcome bad = o;
              bad.ending = isolation::Ending::Exited;
              slots[i] = lostCase(cases[i], bad, options.timeLimitSeconds);
              slots[i]->message = std::string("the case's process handed back an unreadable result: ") + e.what();
            }
          } else {
            slots[i] = lostCase(cases[i], o, options.timeLimitSeconds);
          }
          dirty = true;
          progress.update(++done, cases[i].id);
        });
    if (!complete)
      run.interruptedBy =
          std::string("SIG") +
          (sigabbrev_np(isolation::interruptSignal()) ? sigabbrev_np(isolation::interruptSignal()) : "?");
  }
  progress.finish();

  RunOutcome outcome;
  outcome.complete = complete;
  collect(slots, cases, outcome.results, run.notRun);
  if (identity.profile && identity.profile->probed)
    for (CaseResult& r : outcome.results) markProbedModelFailure(r);
  run.complete = complete;
  run.finished = utcTimestamp();
  BaselineDiff diff;
  if (!options.baseline.empty()) {
    diff = compareWithBaseline(baseline, outcome.results);
    run.baseline = baselineJson(diff, options.baseline.string());
  }
  writeReportFiles(options.outDir, run, outcome.results);

  std::map<Status, int> counts;
  for (const CaseResult& r : outcome.results) ++counts[r.status];
  for (const CaseResult& r : outcome.results)
    if (r.status != Status::Pass) out << "  " << name(r.status) << "  " << r.id << ": " << r.message << "\n";
  if (!options.baseline.empty()) printBaselineDiff(out, diff, options.baseline.string());
  if (!complete)
    out << "INTERRUPTED by " << run.interruptedBy << ": partial report, " << outcome.results.size() << " of "
        << cases.size() << " case(s) ran, " << run.notRun.size() << " not run\n";
  out << "summary:";
  for (Status s : {Status::Pass, Status::Warn, Status::Fail, Status::Skip, Status::Crash, Status::Timeout})
    out << " " << counts[s] << " " << name(s);
  out << "\n" << judgementLines(outcome.results);
  out << "report: " << (options.outDir / "index.html").string() << " (results.json, junit.xml beside it)\n";
  const bool failed = counts[Status::Fail] + counts[Status::Crash] + counts[Status::Timeout] > 0;
  outcome.exitCode = !complete          ? 128 + isolation::interruptSignal()
                     : diff.regressed() ? kExitRegressed
                     : failed           ? kExitFailed
                                        : kExitPass;
  return outcome;
}

}  // namespace voxref::conf
