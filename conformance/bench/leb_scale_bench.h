// The LEB system at scale (issue 18): encode and decode of generated volumes, each step in a
// process of its own (`voxref encode` / `voxref decode`, spawned from this executable), with its
// wall time and its peak resident memory (its VmHWM, polled), the decoded bytes compared with the
// input and the decoded gradients with the input's, bit for bit, and the paper's 2048x2048x1920
// estimated from the largest volume run (or run: lebPaperScaleBench). The volumes are generated
// files in the output folder, removed after the run; never committed.
#pragma once

#include "conformance/bench/bench.h"

namespace voxref::conf {

inline constexpr const char* kLebScaleBenchId = "leb.scale";
BenchTable lebScaleBench(const BenchOptions& options);

// The paper's largest volume, 2048x2048x1920, run the same way (the grid of k = 11). Its encode
// takes about 35 minutes, its decode hours under the resident window (docs/leb.md), and it needs
// 70 GB of scratch disk, so it runs only when the filter is its id exactly, never as part of a
// glob; throws std::runtime_error before writing anything when the output folder's file system
// lacks the disk.
inline constexpr const char* kLebPaperScaleBenchId = "leb.paper_scale";
BenchTable lebPaperScaleBench(const BenchOptions& options);

}  // namespace voxref::conf
