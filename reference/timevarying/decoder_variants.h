// The fragment-shader decoders of the time-varying textures (Binotto et al. 2003, section 6 and
// the appendix), as data shared by the GL path (gpu/shaders/timevarying_*.frag) and its
// emulation. Each decodes the colour of sample point p in [0,1]^3 of time step t with NEAREST
// lookups; they differ in how they address the textures.
//
//   literal       the appendix's Cg ported word for word: `fmod(IN.texCoord, DR / TEX_DIM)` with
//                 the integer macros DR = 8, TEX_DIM = 128 divides by 8 / 128 = 0, and GLSL's
//                 mod(x, 0) is x - 0 * floor(x / 0): NaN. Needs the paper's layout, level 4 of
//                 128^3 data and normalized_rgba8 (the only configuration the macros describe).
//   paper         the same with the division done in float and the layout passed as uniforms:
//                 index at slotOrigin + p / S, refinement at c.xyz + mod(p, 1 / n) * (n / B). The
//                 unorm8 block origins are inexact, so lookups near texel faces can fetch a
//                 neighbouring voxel or block. With normalized_rgba16 or normalized_float index
//                 textures the same shader reads finer or exact origins.
//   texel_centre  block_rgba8 indices; integer block k = round(c.xyz * 255) and voxel offset
//                 floor(mod(p * side, r)) give the refinement texel, addressed at its centre.
//   texel_fetch   block_rgba8 indices; integer texelFetch addressing for both textures.
// The corrected decoders (texel_centre, texel_fetch) fetch the voxel floor(p * side) (clamped to
// side - 1, the GL's CLAMP_TO_EDGE at p = 1.0) for every p: zero wrong voxels.
#pragma once

#include <optional>
#include <string_view>

#include "reference/timevarying/timevarying_codec.h"

namespace voxref::ref {

enum class DecoderVariant { Literal, Paper, TexelCentre, TexelFetch };
std::string_view name(DecoderVariant v);
std::optional<DecoderVariant> parseDecoderVariant(std::string_view s);

// Empty when `variant` can decode textures of this layout and encoding, else why not.
std::string decoderIncompatibility(DecoderVariant variant, const TimeVaryingLayout& layout, IndexEncoding encoding);

}  // namespace voxref::ref
