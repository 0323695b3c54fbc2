// The isosurface benchmarks (Gregorski et al. 2004, Table 2 and section 5): `voxref bench --filter
// 'iso*'`. Table 2's shape with and without occlusion culling, extraction from the compressed
// against the uncompressed volume, and Embree rays per second. Real volumes from benchVolumes().
#pragma once

#include <string>
#include <vector>

#include "conformance/bench/bench.h"
#include "conformance/modules/iso/iso_session.h"

namespace voxref::conf {

std::vector<std::string> isoBenchIds();

// Per-frame averages of a run of runIsoFrames; falseCulls is the total.
struct IsoFrameAverages {
  double triangles = 0, diamonds = 0, tests = 0, culled = 0, frameSeconds = 0;
  double queries = 0, refine = 0, extract = 0, gl = 0, embree = 0;  // the frame time's parts; Embree apart
  std::size_t falseCulls = 0;
};
IsoFrameAverages averageIsoFrames(const std::vector<IsoFrame>& frames);

// Goal 4 of issue 18: the buckyball at the paper's size (1025^3 here, the 1024^3 cells of the
// paper's 1024^3 buckyball: a grid cube needs no padding), end to end in bounded memory
// (iso_scale_bench.cpp). Quick mode: 65^3.
inline constexpr const char* kIsoScaleBenchId = "iso.scale";
BenchTable isoScaleBench(const BenchOptions& options, gpu::Context& gl);
std::vector<BenchTable> isoBench(const BenchOptions& options, gpu::Context& gl);

}  // namespace voxref::conf
