#include "emulation/float32.h"

#include <bit>
#include <cmath>
#include <limits>

namespace voxref::emu {

float unormToFloat(std::uint32_t code, int bits) {
  const float reciprocal = 1.0f / static_cast<float>((std::uint32_t{1} << bits) - 1u);
  return static_cast<float>(code) * reciprocal;
}

std::uint32_t floatToUnormHalfEven(float x, int bits) {
  if (!(x > 0.0f)) return 0;
  const float maxCode = static_cast<float>((std::uint32_t{1} << bits) - 1u);
  if (x >= 1.0f) return static_cast<std::uint32_t>(maxCode);
  return static_cast<std::uint32_t>(std::nearbyint(x * maxCode));
}

std::uint32_t floatToUnormHalfUp(float x, int bits) {
  const float maxCode = static_cast<float>((std::uint32_t{1} << bits) - 1u);
  const float c = x > 0.0f ? (x > 1.0f ? 1.0f : x) : 0.0f;  // CLAMP(x, 0, 1), NaN -> 0
  const float p = c * maxCode;
  return static_cast<std::uint32_t>(p + 0.5f);  // util_iround for f >= 0: (int)(f + 0.5f)
}

std::uint16_t floatToHalfTowardZero(float x) {
  const std::uint32_t f = std::bit_cast<std::uint32_t>(x);
  const std::uint16_t sign = static_cast<std::uint16_t>((f >> 16) & 0x8000u);
  const std::uint32_t absBits = f & 0x7fffffffu;
  if (absBits >= 0x7f800000u)
    return absBits == 0x7f800000u ? sign | 0x7c00u : sign | 0x7e00u | ((absBits >> 13) & 0x3ffu);
  const float a = std::bit_cast<float>(absBits);
  if (a >= 65504.0f) return sign | 0x7bffu;  // round toward zero never reaches infinity
  if (a < std::ldexp(1.0f, -14)) {
    // Subnormal half: quantum 2^-24; truncate.
    return sign | static_cast<std::uint16_t>(std::trunc(std::ldexp(a, 24)));
  }
  int e;
  std::frexp(a, &e);  // a in [2^(e-1), 2^e)
  const int unbiased = e - 1;
  const float mant = std::trunc(std::ldexp(a, 10 - unbiased));  // in [1024, 2048)
  return sign | static_cast<std::uint16_t>(((unbiased + 15) << 10) + (static_cast<int>(mant) - 1024));
}

float halfToFloat(std::uint16_t h) {
  const int exp = (h >> 10) & 0x1f;
  const int mant = h & 0x3ff;
  const float sign = (h & 0x8000u) ? -1.0f : 1.0f;
  if (exp == 0) return sign * std::ldexp(static_cast<float>(mant), -24);
  if (exp == 31) return mant ? std::numeric_limits<float>::quiet_NaN() : sign * std::numeric_limits<float>::infinity();
  return sign * std::ldexp(static_cast<float>(mant + 1024), exp - 25);
}

std::int32_t roundHalfEvenToInt(float x) { return static_cast<std::int32_t>(std::nearbyint(x)); }

std::int32_t softpipeIfloor(float f) {
  // u_math.h, amd64 branch: two doubles offset by 1.5 * 2^23 + 0.5, rounded to float, compared
  // as integers.
  const double af = (3 << 22) + 0.5 + static_cast<double>(f);
  const double bf = (3 << 22) + 0.5 - static_cast<double>(f);
  const std::int32_t ai = std::bit_cast<std::int32_t>(static_cast<float>(af));
  const std::int32_t bi = std::bit_cast<std::int32_t>(static_cast<float>(bf));
  return (ai - bi) >> 1;
}

float glslMod(float x, float y) {
  const float q = x / y;
  const float f = std::floor(q);
  const float m = y * f;
  return x - m;
}

float flushDenormal(float x) { return std::fabs(x) < std::numeric_limits<float>::min() ? std::copysign(0.0f, x) : x; }

}  // namespace voxref::emu
