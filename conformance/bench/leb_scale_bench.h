// The LEB system at scale (issue 18): encode and decode of generated volumes, each step in a
// process of its own (`voxref encode` / `voxref decode`, spawned from this executable), with its
// wall time and its peak resident memory (its VmHWM, polled), the decoded bytes compared with the
// input and the decoded gradients with the input's, bit for bit, and the paper's 2048x2048x1920
// estimated from the largest volume run. The volumes (up to 1024^3) are generated files in the
// output folder, removed after the run; never committed.
#pragma once

#include "conformance/bench/bench.h"

namespace voxref::conf {

inline constexpr const char* kLebScaleBenchId = "leb.scale";
BenchTable lebScaleBench(const BenchOptions& options);

}  // namespace voxref::conf
