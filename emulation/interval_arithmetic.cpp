#include "emulation/interval_arithmetic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "reference/common/rounding.h"

namespace voxref::emu {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool isFloat32(double x) { return static_cast<double>(static_cast<float>(x)) == x; }

// The exact sum a + b of two doubles as s + err (Knuth's TwoSum; needs -ffp-contract=off).
double twoSumError(double a, double b, double s) {
  const double bb = s - a;
  return (a - (s - bb)) + (b - bb);
}

// Either float32 neighbour of the real r = s + err, for the lower (down) or upper bound.
double roundedBound(double s, double err, bool down) {
  if (down) return float32Below(err < 0.0 ? std::nextafter(s, -kInf) : s);
  return float32Above(err > 0.0 ? std::nextafter(s, kInf) : s);
}

Interval roundSum(double a, double b, double c, double d) {
  // [a + b rounded down, c + d rounded up].
  const double lo = a + b, hi = c + d;
  return {roundedBound(lo, twoSumError(a, b, lo), true), roundedBound(hi, twoSumError(c, d, hi), false)};
}

}  // namespace

double float32Below(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

double float32Above(double x) {
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

double ulpF32(double x) {
  // tcu::FloatFormat::ulp (framework/common/tcuFloatFormat.cpp) for binary32: minExp -126, 23
  // fraction bits.
  if (x == 0.0) return ref::powerOfTwo(-149);
  int e = std::ilogb(std::fabs(x));             // |x| in [2^e, 2^(e+1))
  if (std::fabs(x) == ref::powerOfTwo(e)) --e;  // Harrison's ULP at a binade boundary
  return ref::powerOfTwo(std::max(e, -126) - 23);
}

Interval unboundedF32() { return {-kInf, kInf}; }
bool isBounded(const Interval& v) { return std::isfinite(v.lo) && std::isfinite(v.hi); }

Interval addF32(const Interval& a, const Interval& b) {
  if (!isBounded(a) || !isBounded(b)) return unboundedF32();
  return roundSum(a.lo, b.lo, a.hi, b.hi);
}

Interval subF32(const Interval& a, const Interval& b) {
  if (!isBounded(a) || !isBounded(b)) return unboundedF32();
  return roundSum(a.lo, -b.hi, a.hi, -b.lo);
}

Interval mulF32(const Interval& a, const Interval& b) {
  if (!isBounded(a) || !isBounded(b)) return unboundedF32();
  // Products of two float32 values are exact in double (24 + 24 significant bits).
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {float32Below(*std::min_element(p, p + 4)), float32Above(*std::max_element(p, p + 4))};
}

Interval divF32(const Interval& a, const Interval& b, double ulps) {
  if (!isBounded(a) || !isBounded(b)) return unboundedF32();
  const double minDivisor = ref::powerOfTwo(-126), maxDivisor = ref::powerOfTwo(126);
  const bool positive = b.lo >= minDivisor && b.hi <= maxDivisor, negative = b.hi <= -minDivisor && b.lo >= -maxDivisor;
  if (!positive && !negative) return unboundedF32();  // outside the range GLSL gives a precision for
  // a / b is monotone in each argument on this box: its extremes lie at the corners.
  const double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  const double qlo = *std::min_element(q, q + 4), qhi = *std::max_element(q, q + 4);
  // The ULP is taken at the largest magnitude (ULPs grow with it): exact for a point, sound for a range.
  const double maxAbs = std::max(std::fabs(qlo), std::fabs(qhi));
  const double u = qlo == qhi      ? ulpF32(qlo)
                   : maxAbs == 0.0 ? ulpF32(0.0)
                                   : ref::powerOfTwo(std::max(std::ilogb(maxAbs), -126) - 23);
  // Allowed: the float32 values within ulps * u of the exact quotient. The double quotient and the
  // subtraction are each off by at most half a double ULP: two double steps outward cover both.
  const double lo = std::nextafter(std::nextafter(qlo - ulps * u, -kInf), -kInf);
  const double hi = std::nextafter(std::nextafter(qhi + ulps * u, kInf), kInf);
  return {float32Above(lo), float32Below(hi)};
}

Interval floorF32(const Interval& a) {
  if (!isBounded(a)) return unboundedF32();
  return {std::floor(a.lo), std::floor(a.hi)};
}

std::vector<Interval> modF32(const Interval& x, const Interval& y, double divisionUlps) {
  const Interval k = floorF32(divF32(x, y, divisionUlps));
  if (!isBounded(k) || !isBounded(x)) return {unboundedF32()};
  if (k.hi - k.lo > 64)
    throw std::invalid_argument("modF32: the quotient spans more than 64 integers; use a narrower x");
  std::vector<Interval> out;
  for (double i = k.lo; i <= k.hi; ++i) out.push_back(subF32(x, mulF32(y, {i, i})));
  return out;
}

Interval unormToFloatF32(std::uint32_t code, int bits, double divisionUlps) {
  const double maxCode = ref::powerOfTwo(bits) - 1.0;
  if (code == 0) return {0.0, 0.0};
  if (code >= maxCode) return {1.0, 1.0};
  const double c = static_cast<double>(code);
  return divF32({c, c}, {maxCode, maxCode}, divisionUlps);
}

Interval unormCodes(const Interval& value, int bits) {
  const double m = ref::powerOfTwo(bits) - 1.0;
  if (!isBounded(value)) return {0.0, m};
  const double lo = std::clamp(value.lo, 0.0, 1.0), hi = std::clamp(value.hi, 0.0, 1.0);
  // A float32 times 2^b - 1 (b <= 24) is exact in double, so floor and ceil are exact.
  const bool exactLo = isFloat32(lo), exactHi = isFloat32(hi);
  const double sLo = exactLo ? lo * m : std::nextafter(lo * m, -kInf),
               sHi = exactHi ? hi * m : std::nextafter(hi * m, kInf);
  return {std::max(0.0, std::floor(sLo)), std::min(m, std::ceil(sHi))};
}

}  // namespace voxref::emu
