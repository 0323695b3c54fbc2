#include "conformance/runner.h"

#include <chrono>
#include <ctime>
#include <map>
#include <ostream>

#include "conformance/case_context.h"
#include "conformance/catalog.h"
#include "conformance/driver_info.h"
#include "conformance/io/atomic_file.h"
#include "conformance/progress.h"
#include "conformance/report/html_report.h"
#include "conformance/report/junit_xml.h"
#include "conformance/report/results_json.h"
#include "gpu/gl_error.h"

namespace voxref::conf {
namespace {

std::string isoNow() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
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
  const std::vector<Case> cases = selectCases(catalogue, options.filter);
  if (cases.empty()) throw UsageError("no case matches '" + options.filter + "' (voxref list shows them)");
  std::unique_ptr<gpu::Context> gl = gpu::createContext(options.driver);
  std::string how;
  const emu::PrecisionProfile* profile = nullptr;
  try {
    profile = chooseProfile(options.profile, gl->info(), how);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  io::ensureDirectory(options.outDir);

  RunInfo run;
  run.command = options.command;
  run.started = isoNow();
  run.driver = driverJson(gl->info(), profile, how);
  out << "voxref conform: " << cases.size() << " case(s) on " << gl->info().renderer << " (" << gl->info().version << "), profile "
      << (profile ? std::string(profile->name) : std::string("none: envelope oracle alone")) << std::endl;

  CaseContext ctx(gl.get(), profile, options.outDir, options.threads, options.allImages);
  RunOutcome outcome;
  Progress progress("voxref conform", static_cast<long>(cases.size()));
  for (std::size_t i = 0; i < cases.size(); ++i) {
    progress.update(static_cast<long>(i), cases[i].id);
    outcome.results.push_back(runCase(cases[i], ctx));
  }
  progress.finish();
  run.finished = isoNow();

  io::writeFileAtomically(options.outDir / "results.json", resultsJson(run, outcome.results).dump(2) + "\n");
  io::writeFileAtomically(options.outDir / "junit.xml", junitXml(outcome.results));
  io::writeFileAtomically(options.outDir / "index.html", htmlReport(run, outcome.results));

  std::map<Status, int> counts;
  for (const CaseResult& r : outcome.results) ++counts[r.status];
  for (const CaseResult& r : outcome.results)
    if (r.status == Status::Fail || r.status == Status::Crash || r.status == Status::Timeout || r.status == Status::Warn)
      out << "  " << name(r.status) << "  " << r.id << ": " << r.message << "\n";
  out << "summary:";
  for (Status s : {Status::Pass, Status::Warn, Status::Fail, Status::Skip, Status::Crash, Status::Timeout}) out << " " << counts[s] << " " << name(s);
  out << "\nreport: " << (options.outDir / "index.html").string() << " (results.json, junit.xml beside it)\n";
  outcome.exitCode = counts[Status::Fail] + counts[Status::Crash] + counts[Status::Timeout] > 0 ? 1 : 0;
  return outcome;
}

}  // namespace voxref::conf
