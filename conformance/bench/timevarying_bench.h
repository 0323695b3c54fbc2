// The time-varying benchmarks (Binotto et al. 2003, Tables 2 and 3, and the cost of the address
// precision variants): `voxref bench --filter 'timevarying*'`.
#pragma once

#include <string>
#include <vector>

#include "conformance/bench/bench.h"
#include "emulation/profile.h"
#include "gpu/context.h"

namespace voxref::conf {

std::vector<std::string> timeVaryingBenchIds();
std::vector<BenchTable> timeVaryingBench(const BenchOptions& options, gpu::Context& gl,
                                         const emu::PrecisionProfile* profile);

}  // namespace voxref::conf
