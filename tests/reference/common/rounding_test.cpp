#include "reference/common/rounding.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

// powerOfTwo and scaleByPowerOfTwo against libm's ldexp, the definition they replace, over every
// exponent that gives a normal, subnormal, zero or infinite result, and for values of each kind.
TEST(PowerOfTwo, EqualsLdexpBitForBit) {
  for (int e = -1100; e <= 1100; ++e) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(powerOfTwo(e)), std::bit_cast<std::uint64_t>(std::ldexp(1.0, e))) << e;
    for (double x : {0.0, -0.0, 1.0, -3.0, 0.1, 1.0 / 3.0, 1e300, -1e-300, 4.9e-324, 2.2250738585072014e-308,
                     std::numeric_limits<double>::infinity(), std::numeric_limits<double>::max()})
      ASSERT_EQ(std::bit_cast<std::uint64_t>(scaleByPowerOfTwo(x, e)), std::bit_cast<std::uint64_t>(std::ldexp(x, e)))
          << x << " * 2^" << e;
  }
  EXPECT_TRUE(std::isnan(scaleByPowerOfTwo(std::nan(""), 3)));
}

TEST(RoundHalfEven, TiesGoToEven) {
  EXPECT_EQ(roundHalfEven(0.5), 0.0);
  EXPECT_EQ(roundHalfEven(1.5), 2.0);
  EXPECT_EQ(roundHalfEven(2.5), 2.0);
  EXPECT_EQ(roundHalfEven(-0.5), -0.0);
  EXPECT_EQ(roundHalfEven(-1.5), -2.0);
  EXPECT_EQ(roundHalfEven(std::nextafter(0.5, 1.0)), 1.0);
}

TEST(UnormFromDouble, EveryCodeRoundTrips) {
  for (int bits : {8, 12, 16})
    for (std::uint32_t k = 0; k < (1u << bits); ++k)
      ASSERT_EQ(unormFromDouble(unormToDouble(k, bits), bits), k) << bits;
}

TEST(UnormFromDouble, ExactTiesAndClamping) {
  // 0.5 * 255 = 127.5 exactly: a tie, to even.
  EXPECT_EQ(unormFromDouble(0.5, 8), 128u);
  // (k + 0.5) / 255 is not a double; the exact product decides, not the rounded one.
  for (std::uint32_t k = 0; k < 255; ++k) {
    const double mid = (k + 0.5) / 255.0;  // rounded: lies just above or below the true tie
    const long double exact = static_cast<long double>(mid) * 255.0L;
    const std::uint32_t expected = exact > k + 0.5L ? k + 1 : exact < k + 0.5L ? k : (k % 2 ? k + 1 : k);
    ASSERT_EQ(unormFromDouble(mid, 8), expected) << k;
  }
  EXPECT_EQ(unormFromDouble(-1.0, 8), 0u);
  EXPECT_EQ(unormFromDouble(2.0, 8), 255u);
  EXPECT_EQ(unormFromDouble(std::nan(""), 16), 0u);
}

TEST(HalfFromDouble, HandDerivedValues) {
  EXPECT_EQ(halfFromDouble(1.0), 0x3c00);
  EXPECT_EQ(halfFromDouble(-2.0), 0xc000);
  EXPECT_EQ(halfFromDouble(65504.0), 0x7bff);                     // largest finite
  EXPECT_EQ(halfFromDouble(65519.99), 0x7bff);                    // below the overflow tie
  EXPECT_EQ(halfFromDouble(65520.0), 0x7c00);                     // tie between 65504 and 2^16: to even = inf
  EXPECT_EQ(halfFromDouble(std::ldexp(1.0, -24)), 0x0001);        // smallest subnormal
  EXPECT_EQ(halfFromDouble(std::ldexp(1.0, -25)), 0x0000);        // tie 0 / 2^-24: to even 0
  EXPECT_EQ(halfFromDouble(3 * std::ldexp(1.0, -25)), 0x0002);    // tie 1 / 2 (x 2^-24): to even 2
  EXPECT_EQ(halfFromDouble(1.0 + std::ldexp(1.0, -11)), 0x3c00);  // tie: to even mantissa 0
  EXPECT_EQ(halfFromDouble(1.0 + 3 * std::ldexp(1.0, -11)), 0x3c02);
  EXPECT_EQ(halfFromDouble(1.0 + std::ldexp(1.0, -11) + std::ldexp(1.0, -40)), 0x3c01);  // one rounding only
  EXPECT_EQ(halfFromDouble(std::ldexp(1023.5, -24)), 0x0400);  // subnormal carrying into the normals
  EXPECT_EQ(halfFromDouble(-0.0), 0x8000);
  EXPECT_EQ(halfFromDouble(INFINITY), 0x7c00);
  EXPECT_EQ(halfFromDouble(std::nan("")) & 0x7c00, 0x7c00);
}

TEST(HalfToDouble, EveryFiniteHalfRoundTrips) {
  for (std::uint32_t h = 0; h < 0x10000; ++h) {
    if ((h & 0x7c00) == 0x7c00) continue;  // inf / NaN
    ASSERT_EQ(halfFromDouble(halfToDouble(static_cast<std::uint16_t>(h))), h) << std::hex << h;
  }
}

TEST(IsMultipleOfPowerOfTwo, Lattice) {
  EXPECT_TRUE(isMultipleOfPowerOfTwo(0.75, 2));
  EXPECT_FALSE(isMultipleOfPowerOfTwo(0.75, 1));
  EXPECT_TRUE(isMultipleOfPowerOfTwo(6.0, -1));
  EXPECT_FALSE(isMultipleOfPowerOfTwo(INFINITY, 3));
}

}  // namespace
}  // namespace voxref::ref
