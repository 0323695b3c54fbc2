// float32 arithmetic as the GL drivers compute it, one named function per operation whose bits
// matter. Every function is bit-exact against Mesa 22.3.6 (llvmpipe, softpipe) as documented in
// docs/precision.md and verified by the conformance cases; citations are to the Mesa sources.
//
// Compiled with -ffp-contract=off: every C++ float operation below rounds once, to nearest even.
#pragma once

#include <cstdint>

namespace voxref::emu {

// Unorm code -> float as both drivers convert texels and reloaded tiles: k * fl(1 / (2^b - 1)),
// a multiply by the rounded reciprocal, not the correctly rounded k / (2^b - 1)
// (util/u_math.h ubyte_to_float; gallivm lp_build_unsigned_norm_to_float).
float unormToFloat(std::uint32_t code, int bits);

// Float -> unorm code, clamp to [0, 1] then round half to even of fl(x * (2^b - 1)); NaN -> 0.
// llvmpipe's fragment output conversion (lp_bld_conv.c) and softpipe's float_to_ubyte.
std::uint32_t floatToUnormHalfEven(float x, int bits);

// Float -> unorm code as softpipe packs 16-bit targets: trunc(fl(fl(clamp(x) * 65535) + 0.5))
// (util_iround, round half up; generated util_format_r16g16b16a16_unorm_pack_rgba_float).
std::uint32_t floatToUnormHalfUp(float x, int bits);

// binary16 bits of x rounded toward zero; finite overflow gives +-65504, infinities and NaN are
// kept (util/half_float.h _mesa_float_to_float16_rtz; gallivm lp_build_float_to_half).
std::uint16_t floatToHalfTowardZero(float x);
float halfToFloat(std::uint16_t h);  // exact

// Round half to even to an integer (x86 cvtps2dq under the default MXCSR).
std::int32_t roundHalfEvenToInt(float x);

// softpipe's util_ifloor (util/u_math.h:142-150): floor(f), except that a negative f with
// |f| < 2^-29 gives 0. Reproduced operation by operation.
std::int32_t softpipeIfloor(float f);

// GLSL mod(x, y) as Mesa lowers it (nir_opt_algebraic lower_fmod): fl(x - fl(y * floor(fl(x / y)))),
// correctly rounded division, no fused multiply-add.
float glslMod(float x, float y);

// Denormals to signed zero (FTZ / DAZ of llvmpipe's rasterizer threads).
float flushDenormal(float x);

}  // namespace voxref::emu
