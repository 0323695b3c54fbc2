// Stored texel codes: what a texture of a given internal format holds for a real value.
//
// voxref uploads textures as already-encoded integers or half/float bits, so the conversion
// from real data to stored texels happens here, once, for the GL path and its emulation alike.
// Bit-exact: one correctly rounded conversion from double (see rounding.h).
#pragma once

#include <cstdint>

#include "reference/common/gl_state.h"

namespace voxref::ref {

// The stored red-channel code of `value` in `format`:
//   R8, RGBA8 : unorm8 code (clamp to [0,1], round half to even)
//   R16       : unorm16 code
//   R16F      : binary16 bits (round to nearest even)
//   R32F      : binary32 bits (round to nearest even)
std::uint32_t encodeTexel(TexelFormat format, double value);

// The exact real value a stored code stands for (unorm codes: k / (2^b - 1), correctly rounded).
double decodeTexel(TexelFormat format, std::uint32_t code);

// Bytes one texel occupies in GL memory (all channels).
int bytesPerTexel(TexelFormat format);

// Bits of the unorm channel, 0 for float formats.
int unormBits(TexelFormat format);

}  // namespace voxref::ref
