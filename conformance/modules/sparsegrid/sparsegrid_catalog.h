// The built-in sparse-grid cases (Teitzel et al. 1999): the combination technique on GL against
// its emulation and the double reference, over levels, render modes, framebuffer and texture
// formats, and the hard cases. Built-in data is synthetic (reference/common/fields.h).
#pragma once

#include <vector>

#include "conformance/framework/case.h"
#include "conformance/modules/sparsegrid/sparsegrid_scene.h"

namespace voxref::conf {

std::vector<Case> sparseGridCases();

// The scene the catalogue's main cases use, before per-case changes (exposed for `render`
// defaults and tests).
SparseGridScene defaultSparseGridScene();

}  // namespace voxref::conf
