// The LEB system at scale (issue 18): encode and decode of generated volumes, each step in a
// process of its own (`voxref encode` / `voxref decode`, spawned from this executable), with its
// wall time and its peak resident memory (wait4's ru_maxrss of that process alone), and the
// decoded bytes compared with the input bit for bit. The volumes are generated files in the
// output folder, removed after the run; never committed.
#pragma once

#include "conformance/bench/bench.h"

namespace voxref::conf {

inline constexpr const char* kLebScaleBenchId = "leb.scale";
BenchTable lebScaleBench(const BenchOptions& options);

}  // namespace voxref::conf
