// Exact conversions between real values (held as double) and the stored number formats a GL
// implementation uses: unsigned normalized integers and IEEE binary16.
//
// Every function here is bit-exact: it returns the correctly rounded result of the exact real
// operation (one rounding, round half to even unless the name says otherwise), independent of
// the FPU rounding mode and of compiler contraction. Safe on any input, including NaN and
// infinities, which are documented per function.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace voxref::ref {

// Round to the nearest integer, ties to even. Exact for every finite double.
double roundHalfEven(double x);

// The unsigned normalized code of `x` with `bits` bits (1..31): clamp x to [0, 1], then the
// correctly rounded (half to even) value of x * (2^bits - 1). NaN maps to 0.
// This is the conversion GL 4.6 section 2.3.5.2 (equation 2.3) describes for float -> unorm.
std::uint32_t unormFromDouble(double x, int bits);

// The real value a unorm code stands for, k / (2^bits - 1), correctly rounded to double.
double unormToDouble(std::uint32_t code, int bits);

// IEEE 754 binary16 bits of `x`, correctly rounded to nearest, ties to even, with a single
// rounding from double (no intermediate float). Overflow gives +-infinity, NaN a quiet NaN.
std::uint16_t halfFromDouble(double x);

// The exact value of binary16 bits as a double.
double halfToDouble(std::uint16_t h);

// 2^e: the value std::ldexp(1.0, e) returns, for every int e. Built from its bits where 2^e is a
// normal double (e in -1022..1023), without the libm call the envelopes made once per operation.
inline double powerOfTwo(int e) {
  if (e < -1022 || e > 1023) return std::ldexp(1.0, e);  // subnormal, zero or infinity
  return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

// x * 2^e: the value std::ldexp(x, e) returns, for every x and e. Where 2^e is a normal double the
// product is the exact x * 2^e rounded once, as ldexp rounds it.
inline double scaleByPowerOfTwo(double x, int e) {
  if (e < -1022 || e > 1023) return std::ldexp(x, e);
  return x * powerOfTwo(e);
}

// True when `x` is an integer multiple of 2^-exponent2 (exponent2 may be negative).
bool isMultipleOfPowerOfTwo(double x, int exponent2);

}  // namespace voxref::ref
