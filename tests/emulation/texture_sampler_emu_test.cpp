#include "emulation/texture_sampler_emu.h"

#include <bit>
#include <cmath>

#include <gtest/gtest.h>

namespace voxref::emu {
namespace texture_sampler_emu_test {  // named: a unity build compiles several test files together

const PrecisionProfile& llvmpipe() { return *findProfile("llvmpipe"); }
const PrecisionProfile& softpipe() { return *findProfile("softpipe"); }

std::uint32_t f32(float v) { return std::bit_cast<std::uint32_t>(v); }

TEST(Aos8Linear, WeightsAndLerpsInEightBits) {
  // Two texels 10 and 200 along x. s = 0.5: s * 512 = 256, minus 128 -> i0 = 0, w = 128;
  // lerp8 = 10 + floor((128 * 190 + 128) / 256) = 10 + floor(95.5) = 105.
  const std::vector<std::uint32_t> codes{10, 200};
  const TextureSamplerEmu t({2, 1, 1}, ref::TexelFormat::R8, codes, {ref::Filter::Linear, ref::Wrap::ClampToEdge, 0},
                            llvmpipe());
  ASSERT_EQ(t.path(), SamplerPath::Aos8Linear);
  EXPECT_EQ(t.sampleRed(0.5f, 0.5f, 0.5f), 105.0f * 0x1.010102p-8f);
  // s = 0.3: fl(0.3 * 512) = 153.6 -> 154 -> k = 26 -> w = 26: 10 + floor((26 * 190 + 128) / 256) = 29.
  EXPECT_EQ(t.sampleRed(0.3f, 0.5f, 0.5f), 29.0f * 0x1.010102p-8f);
}

TEST(FloatLinear, ExactWeightsGiveExactValues) {
  // R32F texels 0 and 1; s = 0.375: s * 2 - 0.5 = 0.25 = w.
  const std::vector<std::uint32_t> codes{f32(0.0f), f32(1.0f)};
  for (const PrecisionProfile* p : {&llvmpipe(), &softpipe()}) {
    const TextureSamplerEmu t({2, 1, 1}, ref::TexelFormat::R32F, codes,
                              {ref::Filter::Linear, ref::Wrap::ClampToEdge, 0}, *p);
    ASSERT_EQ(t.path(), SamplerPath::FloatLinear);
    EXPECT_EQ(t.sampleRed(0.375f, 0.5f, 0.5f), 0.25f);
  }
}

TEST(FloatLinear, FusedAndUnfusedLerpsDiffer) {
  // a = 1/3, b = 1: w (b - a) + a with one rounding (llvmpipe on FMA CPUs) or three (softpipe).
  const float a = 1.0f / 3.0f, b = 1.0f;
  const std::vector<std::uint32_t> codes{f32(a), f32(b)};
  const float s = 0x1.428f5cp-2f;  // 0.315: found by search to make the two lerps round apart
  const float w = s * 2.0f - 0.5f;
  const float d = b - a;
  const TextureSamplerEmu fused({2, 1, 1}, ref::TexelFormat::R32F, codes,
                                {ref::Filter::Linear, ref::Wrap::ClampToEdge, 0}, llvmpipe());
  const TextureSamplerEmu unfused({2, 1, 1}, ref::TexelFormat::R32F, codes,
                                  {ref::Filter::Linear, ref::Wrap::ClampToEdge, 0}, softpipe());
  EXPECT_EQ(fused.sampleRed(s, 0.5f, 0.5f), std::fma(w, d, a));
  EXPECT_EQ(unfused.sampleRed(s, 0.5f, 0.5f), a + w * d);
  EXPECT_NE(std::fma(w, d, a), a + w * d);  // the test would not discriminate otherwise
}

TEST(Nearest, TexelBoundariesAndBorder) {
  const std::vector<std::uint32_t> codes{f32(0.f), f32(1.f), f32(2.f), f32(3.f)};
  for (const PrecisionProfile* p : {&llvmpipe(), &softpipe()}) {
    const TextureSamplerEmu t({4, 1, 1}, ref::TexelFormat::R32F, codes,
                              {ref::Filter::Nearest, ref::Wrap::ClampToEdge, 0}, *p);
    EXPECT_EQ(t.sampleRed(0.5f, 0.5f, 0.5f), 2.0f);                        // exactly on the boundary: floor
    EXPECT_EQ(t.sampleRed(std::nextafter(0.5f, 0.0f), 0.5f, 0.5f), 1.0f);  // one ulp below
    EXPECT_EQ(t.sampleRed(1.0f, 0.5f, 0.5f), 3.0f);                        // coordinate 1.0 clamps
    const TextureSamplerEmu b({4, 1, 1}, ref::TexelFormat::R32F, codes,
                              {ref::Filter::Nearest, ref::Wrap::ClampToBorder, 0.25}, *p);
    EXPECT_EQ(b.sampleRed(-0.2f, 0.5f, 0.5f), 0.25f);
    const TextureSamplerEmu r({4, 1, 1}, ref::TexelFormat::R32F, codes, {ref::Filter::Nearest, ref::Wrap::Repeat, 0},
                              *p);
    EXPECT_EQ(r.sampleRed(1.3f, 0.5f, 0.5f), 1.0f);  // 1.3 wraps to 0.3: texel 1
  }
}

TEST(SoftpipeTileCache, EarlierTapsReadTheTileThatTookTheirSlot) {
  // A 64 x 1 x 2 texture, value x + 100 z. s = 0.5 puts the x taps on texels 31 and 32 (tiles 0
  // and 1, w = 1/2); r = 0.5 puts the z taps on slices 0 and 1 (w = 1/2). Slot = tile x + z: the
  // tap (31, z1) takes slot 1 from tile (1, z0), so the taps (32, z0) read texel (0, z1) = 100.
  std::vector<std::uint32_t> codes(128);
  for (int z = 0; z < 2; ++z)
    for (int x = 0; x < 64; ++x) codes[x + 64 * z] = f32(static_cast<float>(x + 100 * z));
  const ref::SamplerState st{ref::Filter::Linear, ref::Wrap::ClampToEdge, 0};
  const TextureSamplerEmu sp({64, 1, 2}, ref::TexelFormat::R32F, codes, st, softpipe());
  // z0: 31 + (100 - 31) / 2 = 65.5; z1: 131.5; z: 65.5 + (131.5 - 65.5) / 2 = 98.5.
  EXPECT_EQ(sp.sampleRed(0.5f, 0.5f, 0.5f), 98.5f);
  PrecisionProfile fixed = softpipe();
  fixed.textureTileCache.aliasing = false;
  const TextureSamplerEmu ideal({64, 1, 2}, ref::TexelFormat::R32F, codes, st, fixed);
  EXPECT_EQ(ideal.sampleRed(0.5f, 0.5f, 0.5f), 81.5f);  // (31.5 + 131.5) / 2
}

TEST(TextureSamplerEmu, PathAndEffectsFollowFormatWrapAndProfile) {
  const std::vector<std::uint32_t> codes(8, 0);
  const TextureSamplerEmu border({2, 2, 2}, ref::TexelFormat::R8, codes,
                                 {ref::Filter::Linear, ref::Wrap::ClampToBorder, 0}, llvmpipe());
  EXPECT_EQ(border.path(), SamplerPath::FloatLinear);  // CLAMP_TO_BORDER forces the float path
  const TextureSamplerEmu noaos({2, 2, 2}, ref::TexelFormat::R8, codes, {ref::Filter::Linear, ref::Wrap::Repeat, 0},
                                *findProfile("llvmpipe-noaos"));
  EXPECT_EQ(noaos.path(), SamplerPath::FloatLinear);
  const auto e = TextureSamplerEmu({2, 2, 2}, ref::TexelFormat::R16, codes,
                                   {ref::Filter::Nearest, ref::Wrap::Repeat, 0}, llvmpipe())
                     .effects();
  EXPECT_NE(std::find(e.begin(), e.end(), Effect::SamplerNearest), e.end());
  EXPECT_EQ(std::find(e.begin(), e.end(), Effect::SamplerFloatWeights), e.end());  // NEAREST has no weight stage
}

}  // namespace texture_sampler_emu_test
}  // namespace voxref::emu
