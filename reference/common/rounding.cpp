#include "reference/common/rounding.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace voxref::ref {

double roundHalfEven(double x) {
  // The project never changes the floating-point environment, so nearbyint rounds to nearest,
  // ties to even (C17 7.12.9.3 with FE_TONEAREST, the default of IEEE 754 section 4.3.3).
  return std::nearbyint(x);
}

std::uint32_t unormFromDouble(double x, int bits) {
  if (!(x > 0.0)) return 0;  // also NaN
  const double maxCode = std::ldexp(1.0, bits) - 1.0;
  if (x >= 1.0) return static_cast<std::uint32_t>(maxCode);
  // Exact product x * maxCode = hi + lo (two-product with an explicit fused multiply-add).
  const double hi = x * maxCode;
  const double lo = std::fma(x, maxCode, -hi);
  const double f = std::floor(hi);
  const double frac = hi - f;  // exact
  double r;
  if (frac < 0.5) {
    r = f;
  } else if (frac > 0.5) {
    r = f + 1.0;
  } else if (lo > 0.0) {
    r = f + 1.0;  // the exact product lies above the tie
  } else if (lo < 0.0) {
    r = f;
  } else {
    r = std::fmod(f, 2.0) == 0.0 ? f : f + 1.0;
  }
  return static_cast<std::uint32_t>(r);
}

double unormToDouble(std::uint32_t code, int bits) { return static_cast<double>(code) / (std::ldexp(1.0, bits) - 1.0); }

std::uint16_t halfFromDouble(double x) {
  const std::uint16_t sign = std::signbit(x) ? 0x8000u : 0u;
  if (std::isnan(x)) return 0x7e00u;
  const double a = std::fabs(x);
  if (std::isinf(a)) return sign | 0x7c00u;
  if (a == 0.0) return sign;
  int e;  // a = m * 2^e with m in [0.5, 1)
  std::frexp(a, &e);
  const int unbiased = e - 1;  // a in [2^unbiased, 2^(unbiased+1))
  // Quantum of the binary16 value that holds `a`: 2^(unbiased-10) for normals, 2^-24 below.
  const int quantumExp = unbiased >= -14 ? unbiased - 10 : -24;
  const double m = roundHalfEven(std::ldexp(a, -quantumExp));  // exact scaling, one rounding
  std::uint32_t bitsOut;
  if (quantumExp == -24) {
    bitsOut = static_cast<std::uint32_t>(m);  // subnormal; m == 1024 is the smallest normal
  } else {
    // m in [1024, 2048]; m == 2048 carries into the exponent field, which is the right answer.
    bitsOut = (static_cast<std::uint32_t>(unbiased + 15) << 10) + (static_cast<std::uint32_t>(m) - 1024u);
  }
  if (bitsOut >= 0x7c00u) return sign | 0x7c00u;
  return static_cast<std::uint16_t>(sign | bitsOut);
}

double halfToDouble(std::uint16_t h) {
  const double sign = (h & 0x8000u) ? -1.0 : 1.0;
  const int exp = (h >> 10) & 0x1f;
  const int mant = h & 0x3ff;
  if (exp == 0) return sign * std::ldexp(static_cast<double>(mant), -24);
  if (exp == 31)
    return mant ? std::numeric_limits<double>::quiet_NaN() : sign * std::numeric_limits<double>::infinity();
  return sign * std::ldexp(static_cast<double>(mant + 1024), exp - 25);
}

bool isMultipleOfPowerOfTwo(double x, int exponent2) {
  if (!std::isfinite(x)) return false;
  const double scaled = std::ldexp(x, exponent2);
  return scaled == std::floor(scaled);
}

}  // namespace voxref::ref
