// Running a selection of cases on one driver and writing the report (docs/design.md, `voxref conform`).
//
// Every case runs in its own process (isolation/child_processes.h) with a time limit, so a
// driver that crashes, aborts or hangs costs that case a `crash` or `timeout` status, with the
// process's stdout and stderr kept in the report, and the run goes on. `jobs` processes run at
// once; results do not depend on it (each case's bits come from its own process alone, and the
// report lists cases in catalogue order). Ctrl-C or SIGTERM stops the run and writes a partial
// report that says so.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/report/junit_xml.h"
#include "conformance/framework/shard.h"
#include "gpu/context.h"

namespace voxref::conf {

struct RunOptions {
  std::string filter = "*";
  gpu::Driver driver = gpu::Driver::Llvmpipe;
  std::string profile = "auto";
  std::filesystem::path outDir = "voxref-report";
  int threads = 0;
  bool allImages = false;
  std::string command;              // for the report
  int jobs = 1;                     // case processes at once
  std::optional<Shard> shard;       // run only this shard of the selection
  double timeLimitSeconds = 300.0;  // per case; <= 0: none
  bool inProcess = false;           // no isolation (for a debugger): a crash ends the run
  std::filesystem::path baseline;   // an earlier results.json to compare with; empty: none
  std::string shardFrom;            // what set the shard ("--shard", "CI_NODE_INDEX/CI_NODE_TOTAL"), for the report

  // Running in a CI fleet (docs/ci.md): deqp-runner's expectation files and case lists (each
  // repeatable), flake reruns, every Nth case, checks of the driver's identity before any case.
  std::vector<std::filesystem::path> caseLists, failsFiles, flakesFiles, skipsFiles;
  int flakeReruns = 1;        // reruns of a case that fails unexpectedly; a pass on one is a Flake
  int fraction = 1;           // keep every Nth case of the selection
  std::string rendererCheck;  // ECMAScript regex GL_RENDERER must match (search); empty: none
  std::string versionCheck;   // the same for GL_VERSION
  JunitOptions junit;         // --junit-limit, --junit-template, and the ids' --prefix
  int slowest = 5;            // the slowest cases listed at the end
};

// The driver is not the one the run was told to expect (--renderer-check, --version-check):
// no case ran; exit status 2.
class DriverCheckError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunOutcome {
  std::vector<CaseResult> results;
  bool complete = true;
  int exitCode = kExitPass;
};

// Selects the cases (run_selection.h; UsageError when nothing matches, or for a bad expectation
// file or case list, naming the file and line), learns the driver's identity
// and the profile in a child process (gpu::GlUnavailable when the driver cannot be had,
// UsageError for an unknown profile or an unreadable baseline), runs every case in its own
// process, writes results.json, junit.xml and index.html into outDir (atomically) and prints a
// summary to `out` (DriverCheckError before any case where the renderer or version does not match
// its check). A case that fails unexpectedly is rerun (flakeReruns); every case gets its outcome
// against the expectation files (expectations/outcomes.h), and those decide the exit status:
// kExitFailed where an outcome fails the job. An exception inside a case is its `crash`; so is a signal or an exit
// without a result; a case still running at its time limit is killed and is a `timeout`.
RunOutcome runConformance(const RunOptions& options, const std::vector<Case>& catalogue, std::ostream& out);

// Runs one case in this process, turning GlUnsupported into a skip and any other exception into
// a crash.
CaseResult runCase(const Case& c, class CaseContext& ctx);

}  // namespace voxref::conf
