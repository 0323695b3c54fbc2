#include "emulation/float32.h"

#include <cmath>

#include <gtest/gtest.h>

namespace voxref::emu {
namespace {

TEST(UnormToFloat, MultipliesByTheRoundedReciprocal) {
  // fl(1/255) = 0x1.010102p-8 and fl(1/65535) = 0x1.0001p-16, written out by hand.
  for (std::uint32_t k = 0; k < 256; ++k) ASSERT_EQ(unormToFloat(k, 8), static_cast<float>(k) * 0x1.010102p-8f);
  for (std::uint32_t k = 0; k < 65536; k += 257) ASSERT_EQ(unormToFloat(k, 16), static_cast<float>(k) * 0x1.0001p-16f);
  // Measured on Mesa (research note, docs/precision.md): 126 of the 256 codes differ from the correctly
  // rounded k / 255.
  int differ = 0;
  for (std::uint32_t k = 0; k < 256; ++k) differ += unormToFloat(k, 8) != static_cast<float>(k) / 255.0f;
  EXPECT_EQ(differ, 126);
}

TEST(FloatToUnorm, HalfEvenAsLlvmpipeAndSoftpipeStoreUnorm8) {
  EXPECT_EQ(floatToUnormHalfEven(0.5f, 8), 128u);         // 127.5: tie to even
  EXPECT_EQ(floatToUnormHalfEven(1.5f / 255.0f, 8), 2u);  // measured on both drivers
  EXPECT_EQ(floatToUnormHalfEven(2.5f / 255.0f, 8), 2u);  // measured on both drivers
  EXPECT_EQ(floatToUnormHalfEven(-0.25f, 8), 0u);
  EXPECT_EQ(floatToUnormHalfEven(7.0f, 8), 255u);
  EXPECT_EQ(floatToUnormHalfEven(std::nanf(""), 8), 0u);
  EXPECT_EQ(floatToUnormHalfEven(0.5f, 12), 2048u);  // 2047.5: tie to even
}

TEST(FloatToUnorm, Unorm16RoundingDiffersBetweenDrivers) {
  // x * 65535 is exactly 0.5 + 2^-17 * ... : measured 0 on llvmpipe (RNE) and 1 on softpipe (half up).
  const float x = 0x1.0001p-17f;
  EXPECT_EQ(floatToUnormHalfEven(x, 16), 0u);
  EXPECT_EQ(floatToUnormHalfUp(x, 16), 1u);
  for (std::uint32_t k = 0; k < 65536; k += 97)
    ASSERT_EQ(floatToUnormHalfUp(unormToFloat(k, 16), 16), k);  // reload is lossless
}

TEST(FloatToHalfTowardZero, TruncatesAndSaturates) {
  EXPECT_EQ(floatToHalfTowardZero(0.3f), 0x34cc);  // measured on both drivers; RNE would give 0x34cd
  EXPECT_EQ(floatToHalfTowardZero(-0.3f), 0xb4cc);
  EXPECT_EQ(floatToHalfTowardZero(70000.0f), 0x7bff);  // measured: finite overflow saturates
  EXPECT_EQ(floatToHalfTowardZero(65504.0f), 0x7bff);
  EXPECT_EQ(floatToHalfTowardZero(INFINITY), 0x7c00);
  EXPECT_EQ(floatToHalfTowardZero(1.0f), 0x3c00);
  EXPECT_EQ(floatToHalfTowardZero(1.0f + 0x1.ffp-11f), 0x3c00);  // just below the next half: truncated
  EXPECT_EQ(floatToHalfTowardZero(0x1.8p-24f), 0x0001);          // 1.5 subnormal quanta -> 1
  EXPECT_EQ(floatToHalfTowardZero(0x1p-26f), 0x0000);
  EXPECT_EQ(halfToFloat(0x3c00), 1.0f);
  EXPECT_EQ(halfToFloat(0x0001), 0x1p-24f);
}

TEST(SoftpipeIfloor, FloorWithTheTinyNegativeQuirk) {
  EXPECT_EQ(softpipeIfloor(1.5f), 1);
  EXPECT_EQ(softpipeIfloor(-1.5f), -2);
  EXPECT_EQ(softpipeIfloor(-0.0f), 0);
  EXPECT_EQ(softpipeIfloor(-0x1p-30f), 0);  // measured in the Mesa sources' own test: not -1
  EXPECT_EQ(softpipeIfloor(-0x1p-29f), -1);
  EXPECT_EQ(softpipeIfloor(31.999998f), 31);
}

TEST(RoundHalfEvenToInt, Ties) {
  EXPECT_EQ(roundHalfEvenToInt(2.5f), 2);
  EXPECT_EQ(roundHalfEvenToInt(3.5f), 4);
  EXPECT_EQ(roundHalfEvenToInt(-2.5f), -2);
}

TEST(GlslMod, XMinusYFloorXOverY) {
  EXPECT_EQ(glslMod(5.5f, 2.0f), 1.5f);
  EXPECT_EQ(glslMod(-1.0f, 3.0f), 2.0f);  // floor, not trunc: Cg's fmod would give -1
  // mod(k*y, y) may be about 0 or about y (docs/precision.md); here x / y rounds up to exactly 3.
  EXPECT_EQ(glslMod(0.3f, 0.1f), 0.3f - 0.1f * 3.0f);
}

TEST(FlushDenormal, FlushesOnlyDenormals) {
  EXPECT_EQ(flushDenormal(0x1p-127f), 0.0f);
  EXPECT_TRUE(std::signbit(flushDenormal(-0x1p-130f)));
  EXPECT_EQ(flushDenormal(0x1p-126f), 0x1p-126f);
}

}  // namespace
}  // namespace voxref::emu
