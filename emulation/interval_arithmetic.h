// float32 shader arithmetic on intervals: every value a conforming GLSL implementation may compute
// for an operation whose operands lie in the given intervals (GLSL 4.60 section 4.7.1, "Range and
// Precision", as Khronos dEQP's glsBuiltinPrecisionTests check it), and the GL conversions between
// unorm codes and floats. The envelopes (timevarying_envelope.h) are built from these rules.
//
// Inputs: intervals whose bounds are float32 values (every function here returns such bounds,
// except unboundedF32()); finite, no NaN. Outputs: intervals that contain every allowed result, in
// double. Exactness: each rule is the exact set of allowed float32 results when the operands are
// points, except that division may include one float32 value more on either side (its bounds are
// computed in double and nudged outward); for wider operands the result is the interval hull.
// Integer-valued results (floor, unorm codes) are intervals of integers: every integer inside is a
// possible result.
#pragma once

#include <cstdint>
#include <vector>

#include "emulation/texture_envelope.h"

namespace voxref::emu {

// The largest float32 <= x and the smallest float32 >= x (x within the float32 range).
double float32Below(double x);
double float32Above(double x);

// dEQP's ULP of float32 at x (tcu::FloatFormat::ulp): 2^(e - 23) for |x| in [2^e, 2^(e+1)), the
// spacing below at a power of two (Harrison's ULP), 2^-149 at 0.
double ulpF32(double x);

// The result of an operation whose value the specification leaves open: (-inf, +inf).
Interval unboundedF32();
bool isBounded(const Interval& v);

// a + b, a - b, a * b: correctly rounded, with the rounding mode undefined (GLSL 4.60 section
// 4.7.1: "The rounding mode cannot be set and is undefined"): either float32 neighbour of the exact
// result, the exact result when it is representable.
Interval addF32(const Interval& a, const Interval& b);
Interval subF32(const Interval& a, const Interval& b);
Interval mulF32(const Interval& a, const Interval& b);

// a / b: within `ulps` ULP of the exact quotient (GLSL 4.60 section 4.7.1: 2.5 ULP for |b| in
// [2^-126, 2^126]); unbounded when b reaches outside that range (division by zero included).
Interval divF32(const Interval& a, const Interval& b, double ulps);

// floor(a): exact (dEQP treats floor as a correctly computed function). The integers it may return:
// an interval that straddles an integer yields both sides (the discontinuity).
Interval floorF32(const Interval& a);

// GLSL mod(x, y) = x - y * floor(x / y) (GLSL 4.60 section 8.3: mod; precision "inherited from"
// that expression, section 4.7.1): one interval per integer floor(x / y) may take, in increasing
// order of that integer. Near a multiple of y the division's error makes both x - y k (about 0)
// and x - y (k - 1) (about y) possible. A single unbounded interval when the quotient is unbounded
// (y = 0). For wide x the branches are the hull over x (sound, not tight).
std::vector<Interval> modF32(const Interval& x, const Interval& y, double divisionUlps);

// Unorm code -> float (GL 4.6 section 2.3.5.1, f = c / (2^b - 1)). The GL gives no precision for it;
// voxref grants the precision GLSL grants that division (`divisionUlps`, 2.5), and requires the
// exact value where it is representable (c = 0 -> 0.0, c = 2^b - 1 -> 1.0: nothing forces an
// implementation to miss them, and the Binotto decoders' `alpha == 1.0` test relies on it).
// Mesa's c * fl(1 / (2^b - 1)) is up to 1.25 ULP off for b = 8: inside.
Interval unormToFloatF32(std::uint32_t code, int bits, double divisionUlps);

// Float -> unorm code (GL 4.6 section 2.3.5.2): clamp to [0, 1], then convert_float_uint, "one of
// the two closest" integers to f (2^b - 1). For an interval: [floor(lo m), ceil(hi m)], m = 2^b - 1.
Interval unormCodes(const Interval& value, int bits);

}  // namespace voxref::emu
