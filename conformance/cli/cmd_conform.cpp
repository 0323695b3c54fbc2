#include <iostream>

#include "conformance/catalog.h"
#include "conformance/cli/commands.h"
#include "conformance/runner.h"
#include "gpu/gl_error.h"

namespace voxref::cli {

int runConform(const ConformOptions& o) {
  conf::RunOptions run;
  const auto driver = gpu::parseDriver(o.driver);
  if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "' (llvmpipe, softpipe or egl)");
  run.driver = *driver;
  run.filter = o.filter;
  run.profile = o.profile;
  run.outDir = o.out;
  run.threads = o.threads;
  run.allImages = o.allImages;
  run.command = o.command;
  try {
    return conf::runConformance(run, conf::allCases(), std::cout).exitCode;
  } catch (const gpu::GlUnavailable& e) {
    std::cerr << "voxref: no GL context for --driver " << o.driver << ": " << e.what() << "\n";
    return 2;
  }
}

}  // namespace voxref::cli
