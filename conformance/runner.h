// Running a selection of cases on one driver and writing the report (DESIGN.md, `voxref conform`).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "conformance/case.h"
#include "gpu/context.h"

namespace voxref::conf {

// A mistake in the command (unknown case, unknown profile, bad option value): exit status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunOptions {
  std::string filter = "*";
  gpu::Driver driver = gpu::Driver::Llvmpipe;
  std::string profile = "auto";
  std::filesystem::path outDir = "voxref-report";
  int threads = 0;
  bool allImages = false;
  std::string command;  // for the report
};

struct RunOutcome {
  std::vector<CaseResult> results;
  int exitCode = 0;  // 0 only when no case failed, crashed or timed out
};

// Selects the cases (UsageError when the filter matches none), creates the GL context
// (gpu::GlUnavailable when the driver cannot be had), chooses the profile (UsageError for an
// unknown name), runs every case, writes results.json, junit.xml and index.html into outDir
// (atomically) and prints a summary to `out`. Exceptions inside a case become its `crash`.
RunOutcome runConformance(const RunOptions& options, const std::vector<Case>& catalogue, std::ostream& out);

// Runs one case, turning GlUnsupported into a skip and any other exception into a crash.
CaseResult runCase(const Case& c, class CaseContext& ctx);

}  // namespace voxref::conf
