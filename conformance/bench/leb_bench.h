// The LEB compression benchmarks (Gregorski et al. 2004, Table 1 and section 5's decode speeds):
// `voxref bench --filter 'leb*'`. CPU only; the real volumes come from benchVolumes().
#pragma once

#include <string>
#include <vector>

#include "conformance/bench/bench.h"

namespace voxref::conf {

std::vector<std::string> lebBenchIds();
std::vector<BenchTable> lebBench(const BenchOptions& options);

}  // namespace voxref::conf
