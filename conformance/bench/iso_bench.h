// The isosurface benchmarks (Gregorski et al. 2004, Table 2 and section 5): `voxref bench --filter
// 'iso*'`. Table 2's shape with and without occlusion culling, extraction from the compressed
// against the uncompressed volume, and Embree rays per second. Real volumes from benchVolumes().
#pragma once

#include <string>
#include <vector>

#include "conformance/bench/bench.h"

namespace voxref::conf {

std::vector<std::string> isoBenchIds();
std::vector<BenchTable> isoBench(const BenchOptions& options, gpu::Context& gl);

}  // namespace voxref::conf
