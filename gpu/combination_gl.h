// The paper's hardware method on a real GL context (Teitzel et al. 1999, section 6, calcValueRect):
// for every sampling plane, clear, draw every component grid's texture as a full-screen pass
// with blending ONE/ONE and the pass's equation, read the plane back.
#pragma once

#include <functional>

#include "gpu/context.h"
#include "gpu/shader_override.h"
#include "reference/common/framebuffer_codes.h"
#include "reference/common/plane_frame.h"
#include "reference/sparsegrid/combination_textures.h"

namespace voxref::gpu {

struct CombinationGlOptions {
  // glFinish after every pass. Real hardware and llvmpipe quantize the framebuffer after every
  // blend anyway; softpipe keeps float colours in its tile cache until a flush, so this is how to
  // obtain the per-pass semantics from it (a finding of voxref, see docs/precision.md).
  bool flushEachPass = false;
  // A user's fragment shader in place of combination.frag (shader_override.h); nullptr or
  // another stage's: the built-in shader.
  const ShaderOverride* shader = nullptr;
};

// The red-channel codes of every plane. Throws GlUnsupported when a texture or the target does
// not fit the context's limits (or the format is RGBA12), GlError / ShaderError on GL failures
// (ShaderError also when options.shader does not compile).
// `progress` is called with the number of planes finished.
ref::CodePlanes renderCombinationGl(Context& context, const ref::CombinationTextures& textures,
                                    const ref::PlaneFrame& frame, const ref::SamplerState& sampler,
                                    ref::FramebufferFormat format, const CombinationGlOptions& options = {},
                                    const std::function<void(int)>& progress = {});

}  // namespace voxref::gpu
