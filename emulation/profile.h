// Precision profiles: what a GL implementation computes, as named data (docs/design.md).
//
// A profile selects, for every stage whose bits can differ between implementations, one of the
// arithmetic variants the emulator implements (each implemented once, in the stage's file). The
// values of the Mesa 22.3.6 profiles come from docs/precision.md and from reading the Debian 22.3.6
// sources (texture sampling: gallivm lp_bld_sample_soa.c / lp_bld_sample_aos.c, softpipe
// sp_tex_sample.c; framebuffers: lp_state_fs.c, lp_bld_blend.c, sp_quad_blend.c,
// sp_tile_cache.c); the conformance cases `sparsegrid.*` verify them bit for bit.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "emulation/effects.h"

namespace voxref::emu {

// Coordinate, wrap and filter formulas of a sampler implementation.
enum class SamplerFamily {
  Llvmpipe,  // gallivm SoA (lp_build_sample_wrap_linear / _nearest)
  Softpipe,  // sp_tex_sample.c (wrap_linear_* / wrap_nearest_*, util_ifloor)
};

enum class LerpArithmetic {
  Fused,    // fma(w, v1 - v0, v0): llvm.fmuladd on a CPU with FMA
  Unfused,  // v0 + w * (v1 - v0), three roundings
};

enum class FramebufferModel {
  QuantizePerPass,  // every blend reads and writes the stored format (llvmpipe, real hardware)
  FloatTileCache,   // float32 tiles; stored format written only on flush or eviction (softpipe)
};

enum class UnormRounding { HalfEven, HalfUp };

// How the 8-bit path rounds each lerp back to 8 bits: a + ((w (b - a) + 128) >> 8) with SSSE3's
// pmulhrsw, a + ((w (b - a)) >> 8) without it (lp_bld_arit.c, lp_build_lerp; measured by the probe's
// sampling.unorm8.lerp_rounding under GALLIUM_OVERRIDE_CPU_CAPS=sse3).
enum class Lerp8Rounding { Nearest, Floor };

// softpipe's texture tile cache (sp_tex_tile_cache.[ch]): direct mapped, `slots` entries of
// tileSize x tileSize texels, slot = (tile x + yMultiplier * tile y + z) % slots for level 0.
// img_filter_3d_linear (sp_tex_sample.c:1873-1918) takes all eight texel *pointers* into the
// cache before it reads them, so a later tap whose tile shares a slot with an earlier tap's tile
// overwrites the entry the earlier pointer reads: that tap returns the texel at the same
// position inside the later tile. voxref found this by the conformance cases; `aliasing` models it.
struct TextureTileCache {
  bool aliasing = false;
  int tileSize = 32;
  int slots = 16;
  int yMultiplier = 9;
};

struct PrecisionProfile {
  std::string_view name;
  std::string_view summary;
  std::string_view renderer;  // GL_RENDERER prefix it describes
  SamplerFamily sampler = SamplerFamily::Llvmpipe;
  // llvmpipe's 8-bit fixed-point ("AoS") path for unorm8 formats whose wraps are all REPEAT or
  // CLAMP_TO_EDGE: 8 subtexel bits, 8-bit lerps rounded as pmulhrsw does.
  bool aos8BitSampling = false;
  Lerp8Rounding aosLerp = Lerp8Rounding::Nearest;
  LerpArithmetic floatLerp = LerpArithmetic::Unfused;
  bool flushDenormals = false;        // FTZ/DAZ in texture filtering and float32 blending
  TextureTileCache textureTileCache;  // softpipe only
  // The compiler folds a product with the constant 0 to 0, so GLSL's mod(x, 0.0) written with a
  // literal zero is x (Mesa's nir_opt_algebraic `~fmul(a, 0.0)`); with a zero it cannot see (a
  // uniform) mod(x, 0) is x - 0 * floor(x / 0) = NaN. Measured on both Mesa drivers.
  bool foldsMultiplyByConstantZero = true;
  // texelFetch outside the texture (undefined by the spec): llvmpipe returns (0, 0, 0, 0),
  // softpipe clamps every coordinate to the edge (measured, research note 2).
  bool texelFetchOutOfRangeClamps = false;
  FramebufferModel framebuffer = FramebufferModel::QuantizePerPass;
  UnormRounding unorm16Store = UnormRounding::HalfEven;  // float -> unorm16 of the colour buffer
  // The largest colour target the model holds for: softpipe's 50-entry tile cache evicts (and
  // quantizes) tiles of targets wider than 320 or taller than 640 pixels.
  int maxModelledTargetWidth = 1 << 30;
  int maxModelledTargetHeight = 1 << 30;
  std::string_view environment;  // the driver environment this profile describes
  // Built by `voxref probe` from what it measured rather than calibrated by hand
  // (conformance/framework/probe/probed_profile.h): an exact failure against it says the probed
  // model does not hold, not that the driver regressed.
  bool probed = false;
};

std::span<const PrecisionProfile> knownProfiles();
// nullptr for an unknown name.
const PrecisionProfile* findProfile(std::string_view name);

// Where a profile departs from what the GL specification's semantics (and real hardware) give for
// the same state: each departure names the behaviour and describes the semantics to compare with,
// as the same profile with that behaviour removed plus a flag for per-pass flushes. A case run
// under a profile with departures reports, per departure, how many samples they change.
struct Departure {
  std::string_view id;  // "softpipe.framebuffer.no_per_pass_requantization"
  std::string_view description;
  PrecisionProfile semantics;  // the profile without this behaviour
  bool flushEachPass = false;  // the semantics are obtained with a flush after every pass
  Effect effect;               // the simulated effect that is this behaviour
};
std::vector<Departure> departuresFromGlSemantics(const PrecisionProfile& profile);
// The departures a scene meets: those whose effect is among the effects its emulation simulates
// (a NEAREST-only scene never meets the LINEAR tile-cache aliasing, so it is not reported).
std::vector<Departure> departuresAmong(const PrecisionProfile& profile, std::span<const Effect> simulated);

// The profile `auto` picks for a renderer string, the environment and the CPU's FMA support:
// llvmpipe[-noaos][-nofma] or softpipe. nullptr for an unknown renderer (a driver voxref has no
// profile for: judged by the envelope oracle alone).
const PrecisionProfile* autoProfile(std::string_view renderer, std::string_view gallivmPerf,
                                    std::string_view overrideCpuCaps, bool cpuHasFma);

}  // namespace voxref::emu
