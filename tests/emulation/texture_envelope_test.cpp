#include "emulation/texture_envelope.h"

#include <bit>
#include <cmath>

#include <gtest/gtest.h>

namespace voxref::emu {
namespace {

TEST(EnvelopeErrors, AsDeqpComputesThem) {
  // computeFloatingPointError(1.0, 20): (2^3 - 1) units of 2^-23.
  EXPECT_EQ(floatingPointError(1.0, 20), 7 * std::ldexp(1.0, -23));
  EXPECT_EQ(floatingPointError(0.75, 20), 7 * std::ldexp(1.0, -24));
  EXPECT_EQ(fixedPointError(7), (std::ldexp(1.0, 16) - 1) * std::ldexp(1.0, -23));
}

TEST(TextureEnvelope, ContainsTheExactLookupAndNothingFarFromIt) {
  const std::vector<std::uint32_t> codes{std::bit_cast<std::uint32_t>(0.0f), std::bit_cast<std::uint32_t>(1.0f)};
  const TextureEnvelope e({2, 1, 1}, ref::TexelFormat::R32F, codes, {ref::Filter::Linear, ref::Wrap::ClampToEdge, 0});
  // u = 0.375: exact weight 0.25. The interval is 0.25 +- (coordinate + subtexel error) * N:
  // about 2^-7 for 7 subtexel bits.
  const Interval i = e.lookup({0.375, 0.5, 0.5}, kEnvelopePass);
  EXPECT_TRUE(i.contains(0.25));
  EXPECT_GT(i.lo, 0.25 - 0.01);
  EXPECT_LT(i.hi, 0.25 + 0.01);
  const Interval w = e.lookup({0.375, 0.5, 0.5}, kEnvelopeQualityWarning);  // 4 subtexel bits: wider
  EXPECT_LT(w.lo, i.lo);
  EXPECT_GT(w.hi, i.hi);
  const TextureEnvelope n({2, 1, 1}, ref::TexelFormat::R32F, codes, {ref::Filter::Nearest, ref::Wrap::ClampToEdge, 0});
  const Interval onBoundary = n.lookup({0.5, 0.5, 0.5}, kEnvelopePass);  // either texel may be taken
  // (Bounds are padded outward by 2^-40 relative.)
  EXPECT_LE(onBoundary.lo, 0.0);
  EXPECT_GE(onBoundary.hi, 1.0);
  EXPECT_GT(onBoundary.lo, -1e-9);
  EXPECT_LT(onBoundary.hi, 1.0 + 1e-9);
}

}  // namespace
}  // namespace voxref::emu
