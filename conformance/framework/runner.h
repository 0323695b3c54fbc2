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
};

struct RunOutcome {
  std::vector<CaseResult> results;
  bool complete = true;
  int exitCode = kExitPass;
};

// Selects the cases (UsageError when the filter matches none), learns the driver's identity
// and the profile in a child process (gpu::GlUnavailable when the driver cannot be had,
// UsageError for an unknown profile or an unreadable baseline), runs every case in its own
// process, writes results.json, junit.xml and index.html into outDir (atomically) and prints a
// summary to `out`. An exception inside a case is its `crash`; so is a signal or an exit
// without a result; a case still running at its time limit is killed and is a `timeout`.
RunOutcome runConformance(const RunOptions& options, const std::vector<Case>& catalogue, std::ostream& out);

// Runs one case in this process, turning GlUnsupported into a skip and any other exception into
// a crash.
CaseResult runCase(const Case& c, class CaseContext& ctx);

}  // namespace voxref::conf
