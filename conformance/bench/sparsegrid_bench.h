// The sparse-grid benchmarks (Teitzel et al. 1999, Tables 1 and 2, and the accuracy of every
// framebuffer format against the double reference): `voxref bench --filter 'sparsegrid*'`.
#pragma once

#include <string>
#include <vector>

#include "conformance/bench/bench.h"
#include "emulation/profile.h"
#include "gpu/context.h"

namespace voxref::conf {

std::vector<std::string> sparseGridBenchIds();
// study.sparsegrid (study.h): framebuffer formats and texture formats on GL, and the sampler
// paths of every known profile through their emulations.
BenchTable sparseGridStudy(const BenchOptions& options, gpu::Context& gl, const emu::PrecisionProfile* profile);
std::vector<BenchTable> sparseGridBench(const BenchOptions& options, gpu::Context& gl,
                                        const emu::PrecisionProfile* profile);

}  // namespace voxref::conf
