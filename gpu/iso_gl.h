// The isosurface on a real GL context (Gregorski et al. 2004, sections 4 and 5): the extracted
// mesh drawn from indexed vertex buffers with two-sided headlight Lambert shading
// (reference/iso/iso_shading.h) into RGBA8 + an R32UI triangle-id buffer + a float32 depth buffer, and occlusion queries on
// axis-aligned boxes against the depth of a mesh (the previous frame's surface, as the paper).
//
// Conventions are ref::ViewCamera's (row 0 at the bottom, the pixel centre is the sample point).
// The MVP matrix is computed in double and rounded to float once.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gpu/context.h"
#include "reference/common/view_camera.h"
#include "reference/iso/iso_mesh.h"

namespace voxref::gpu {

struct IsoImageGl {
  int width = 0, height = 0;
  std::vector<std::array<std::uint8_t, 4>> rgba;  // row 0 at the bottom
  std::vector<float> windowDepth;                 // GL window depth in [0, 1]; 1 where nothing was drawn
  std::vector<std::uint32_t> primitive;           // index of the triangle drawn (gl_PrimitiveID) + 1; 0: none
};

// Renders the mesh. Throws GlUnsupported when the size exceeds GL_MAX_RENDERBUFFER_SIZE.
IsoImageGl renderIsoMeshGl(Context& context, const ref::IsoMesh& mesh, const ref::ViewCamera& camera);

struct QueryBox {
  std::array<double, 3> lo, hi;  // grid coordinates
};

// For every box, the samples that pass GL_LEQUAL against the depth of `occluder` (rendered first,
// depth only) from `camera`: GL_SAMPLES_PASSED, one query per box. A box whose extent reaches
// within the near plane of the eye cannot be tested (it would be clipped): its count is reported
// as kNotTested and the caller must treat it as visible.
inline constexpr std::uint32_t kNotTested = 0xffffffffu;
std::vector<std::uint32_t> occlusionQueriesGl(Context& context, const ref::IsoMesh& occluder, const std::vector<QueryBox>& boxes,
                                              const ref::ViewCamera& camera);

}  // namespace voxref::gpu
