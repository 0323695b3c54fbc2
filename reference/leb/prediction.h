// Difference-from-linear prediction along a diamond's split edge (Gregorski et al. 2004, section
// 3.1, equations 1 and 2), in exact integer arithmetic, for b-bit samples.
//
// Equation 1 averages the two endpoint values; voxref rounds the average down (an arithmetic
// shift, also for signed values), so D_p = floor((D_SV0 + D_SV1) / 2). The delta of equation 2 is
// taken modulo 2^b and stored as a b-bit two's complement value, so it always fits the b + 1
// lead-1 symbols of section 3.1 ("8 bits ... 256 possible values"). Root corners have no split
// edge: their prediction is 0. Points of the padding (outside the original volume) are not coded
// at all: their value is defined to be their prediction (delta 0), which costs no bits and keeps
// every prediction inside the volume defined.
#pragma once

#include <cstdint>

namespace voxref::ref {

inline std::int32_t predictMidpoint(std::int32_t a, std::int32_t b) { return (a + b) >> 1; }

// x modulo 2^bits as a two's complement value in [-2^(bits-1), 2^(bits-1)).
inline std::int32_t wrapSigned(std::int32_t x, int bits) {
  const std::uint32_t mask = (bits == 32) ? ~0u : ((1u << bits) - 1);
  const std::uint32_t m = static_cast<std::uint32_t>(x) & mask;
  return (m >> (bits - 1)) ? static_cast<std::int32_t>(m) - static_cast<std::int32_t>(1u << bits)
                           : static_cast<std::int32_t>(m);
}

// A sample of `bits` bits (unsigned, or two's complement when isSigned) as the int32 the predictor
// works on, and back.
inline std::int32_t wrapSample(std::int32_t x, int bits, bool isSigned) {
  return isSigned ? wrapSigned(x, bits) : static_cast<std::int32_t>(static_cast<std::uint32_t>(x) & ((1u << bits) - 1));
}

inline std::int32_t predictionDelta(std::int32_t value, std::int32_t prediction, int bits) {
  return wrapSigned(value - prediction, bits);
}
inline std::int32_t reconstructSample(std::int32_t prediction, std::int32_t delta, int bits, bool isSigned) {
  return wrapSample(prediction + delta, bits, isSigned);
}

}  // namespace voxref::ref
