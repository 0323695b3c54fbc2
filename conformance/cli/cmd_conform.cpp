#include <iostream>

#include "conformance/cli/case_selection.h"
#include "conformance/cli/commands.h"
#include "conformance/framework/runner.h"
#include "gpu/gl_error.h"

namespace voxref::cli {

int runConform(const ConformOptions& o) {
  conf::RunOptions run;
  const auto driver = gpu::parseDriver(o.driver);
  if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "' (llvmpipe, softpipe or egl)");
  if (o.inProcess && o.runnerControls) throw conf::UsageError("--in-process cannot run the runner's control cases: they end the process");
  if (o.timeout < 0) throw conf::UsageError("--timeout must be 0 (none) or a number of seconds");
  run.driver = *driver;
  run.filter = o.filter;
  run.profile = o.profile;
  run.outDir = o.out;
  run.threads = o.threads;
  run.allImages = o.allImages;
  run.command = o.command;
  run.jobs = o.jobs;
  run.shard = shardOption(o.shard);
  run.timeLimitSeconds = o.timeout;
  run.inProcess = o.inProcess;
  run.baseline = o.baseline;
  try {
    return conf::runConformance(run, catalogue(o.runnerControls), std::cout).exitCode;
  } catch (const gpu::GlUnavailable& e) {
    std::cerr << "voxref: no GL context for --driver " << o.driver << ": " << e.what() << "\n";
    return 2;
  }
}

}  // namespace voxref::cli
