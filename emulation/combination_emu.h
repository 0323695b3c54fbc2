// The paper's hardware method emulated on the CPU (Teitzel et al. 1999, section 6): for every
// sample of every plane, the fragment shader's float32 arithmetic (gpu/shaders/combination.frag),
// the driver's texture sampling and the framebuffer's blending, pass after pass, under a profile.
//
// Bit-exact: returns the codes the GL path reads back, on the implementation the profile
// describes. Deterministic for every thread count (samples are independent).
#pragma once

#include <functional>
#include <vector>

#include "emulation/effects.h"
#include "emulation/profile.h"
#include "reference/common/framebuffer_codes.h"
#include "reference/common/plane_frame.h"
#include "reference/sparsegrid/combination_textures.h"

namespace voxref::emu {

struct CombinationEmuOptions {
  bool flushEachPass = false;  // mirrors gpu::CombinationGlOptions::flushEachPass
  int threads = 0;             // 0: hardware concurrency
  // Run every stage the pruning skips for this state anyway, as identities (issue 7: pruning
  // measured): the NEAREST sampler's weight stage (TextureSamplerEmu) and the float formats'
  // per-pass clamp and float32 tile store (BlendEmu). Same bits; only the time differs.
  bool forceAllEffects = false;
};

struct EmulatedPlanes {
  ref::CodePlanes planes;
  // 1 where the code depends on state the model does not hold (texture_sampler_emu.h); such
  // samples are reported and excluded from exact comparison by name, never silently.
  std::vector<std::uint8_t> unmodelled;
  std::size_t unmodelledCount = 0;
};

// Throws std::invalid_argument when the profile cannot model the target size (framebuffer_emu.h).
EmulatedPlanes emulateCombination(const ref::CombinationTextures& textures, const ref::PlaneFrame& frame,
                                  const ref::SamplerState& sampler, ref::FramebufferFormat format,
                                  const PrecisionProfile& profile, const CombinationEmuOptions& options = {},
                                  const std::function<void(int)>& progress = {});

// The effects emulateCombination simulates for this state: the union over the textures' sampling
// stages, the address rounding when a texture extent is not a power of two, and the framebuffer.
std::vector<Effect> combinationEffects(const ref::CombinationTextures& textures, const ref::SamplerState& sampler,
                                       ref::FramebufferFormat format, const PrecisionProfile& profile,
                                       const CombinationEmuOptions& options, int width, int height);

// The float32 texture coordinate the shader computes in a brick starting at texel `origin`:
// fl(fl(fl(fl(p * 2^l) + 0.5) - origin) / extent).
float combinationTexCoord(float p, int level, int extent, int origin = 0);

}  // namespace voxref::emu
