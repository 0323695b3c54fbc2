// Figure 9 of Teitzel et al. 1999 in 3D: without scaling, the per-pass clamping of a fixed-point
// framebuffer makes EVERY order of adds and subtracts wrong for some sample; with the paper's
// scaling by 1/n+ every sample is right within the quantization bound.
//
// Data: the `figure9` field on a level-2 sparse grid with boundary: component grids
// A = (2,1,1), B = (1,2,1), C = (1,1,2) (+1) and N = (1,1,1) (-2). Unscaled, the method draws
// +A +B +C -N -N: 5!/2! = 60 distinct orders. Exact rational arithmetic (docs/sparsegrid.md,
// "Figure 9") shows that each order is wrong by at least 0.6 at one of (1/2,1/2,1/2),
// (1/4,1/2,1/2), (1/2,1/4,1/2), (1/2,1/2,1/4); the cases verify it on GL and emulation.
#pragma once

#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

std::vector<Case> figure9Cases();

}  // namespace voxref::conf
