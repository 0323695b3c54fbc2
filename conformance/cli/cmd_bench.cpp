#include <iostream>

#include "conformance/bench/bench.h"
#include "conformance/cli/commands.h"
#include "conformance/framework/runner.h"

namespace voxref::cli {

int runBench(const BenchOptions& o) {
  const auto driver = gpu::parseDriver(o.driver);
  if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "'");
  conf::BenchOptions b{o.filter, o.out, *driver, o.quick, o.threads, o.volumes};
  return conf::runBenchmarks(b, std::cout);
}

}  // namespace voxref::cli
