#include "emulation/timevarying_emu.h"

#include <cmath>

#include <gtest/gtest.h>

#include "emulation/float32.h"
#include "emulation/framebuffer_emu.h"
#include "reference/timevarying/plume.h"

namespace voxref::emu {
namespace {

TEST(Mulnorm8, IsLlvmpipesRoundingNotRoundToNearest) {
  // t = 152 * 229 = 34808; (t + (t >> 8) + 128) >> 8 = (34808 + 135 + 128) >> 8 = 136, while
  // round(34808 / 255) = round(136.50) = 137: one of the 12 products where they differ.
  EXPECT_EQ(mulnorm8(152, 229), 136);
  int differ = 0;
  for (int a = 0; a < 256; ++a)
    for (int b = 0; b < 256; ++b)
      differ += mulnorm8(std::uint8_t(a), std::uint8_t(b)) != static_cast<int>(std::lround(a * b / 255.0));
  EXPECT_EQ(differ, 24);  // 12 products, each as (a, b) and (b, a): measured on llvmpipe (research note 2)
  EXPECT_EQ(mulnorm8(255, 255), 255);
  EXPECT_EQ(mulnorm8(0, 255), 0);
}

TEST(AlphaBlendEmu, OpaqueReplacesTransparentKeeps) {
  for (const char* name : {"llvmpipe", "softpipe"}) {
    const AlphaBlendEmu b(*findProfile(name));
    AlphaBlendEmu::Pixel px = b.cleared();
    b.blend(px, {0.2f, 0.4f, 0.6f, 1.0f});  // alpha 1: the source replaces the destination
    EXPECT_EQ(b.resolve(px), (std::array<std::uint8_t, 4>{51, 102, 153, 255})) << name;
    b.blend(px, {1.0f, 1.0f, 1.0f, 0.0f});  // alpha 0: nothing changes
    EXPECT_EQ(b.resolve(px), (std::array<std::uint8_t, 4>{51, 102, 153, 255})) << name;
  }
}

TEST(AlphaBlendEmu, TenLayersRoundPerPassOnLlvmpipeOnceOnSoftpipe) {
  // Ten layers of (0.5, alpha 0.1): llvmpipe quantizes every layer, softpipe keeps float32.
  auto ten = [](const char* name, bool flush) {
    const AlphaBlendEmu b(*findProfile(name), flush);
    AlphaBlendEmu::Pixel px = b.cleared();
    for (int i = 0; i < 10; ++i) b.blend(px, {0.5f, 0.5f, 0.5f, 0.1f});
    return b.resolve(px);
  };
  // softpipe, float32: red = 0.5 * (1 - 0.9^10) = 0.3257 -> 83.06 LSB -> 83.
  EXPECT_EQ(ten("softpipe", false)[0], 83);
  // llvmpipe by hand: s = RNE(127.5) = 128, a = RNE(25.5) = 26, 255 - a = 229;
  // d <- mulnorm(128, 26) + mulnorm(d, 229) = 13 + ...: 13, 25, 35, 44, 53, 61, 68, 74, 79, 84.
  EXPECT_EQ(ten("llvmpipe", false)[0], 84);
}

TEST(TimeVaryingDecoderEmu, CorrectedDecodersReadEveryVoxelCentreExactly) {
  const ref::TimeSeries s = ref::driftingBlobs(16, 3);
  const ref::TransferFunction tf = ref::transferFunction("gray");
  ref::TimeVaryingOptions o{2, ref::IndexEncoding::BlockRgba8};
  const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(s, tf, o);
  for (ref::DecoderVariant v : {ref::DecoderVariant::TexelCentre, ref::DecoderVariant::TexelFetch}) {
    const TimeVaryingDecoderEmu d(tex, v, *findProfile("llvmpipe"));
    for (int t = 0; t < 3; ++t)
      for (int z = 0; z < 16; z += 3)
        for (int y = 0; y < 16; ++y)
          for (int x = 0; x < 16; ++x) {
            const glm::vec3 p((x + 0.5f) / 16, (y + 0.5f) / 16, (z + 0.5f) / 16);
            const DecodedSample smp = d.decode(t, p);
            const ref::Rgba8 want = tf(s.steps[t][x + 16 * (y + 16 * z)]);
            for (int c = 0; c < 4; ++c) ASSERT_EQ(floatToUnormHalfEven(smp.value[c], 8), want[c]);
          }
  }
  EXPECT_THROW(TimeVaryingDecoderEmu(tex, ref::DecoderVariant::Paper, *findProfile("llvmpipe")), std::invalid_argument);
}

TEST(TimeVaryingDecoderEmu, LiteralModByZeroFoldsOrGivesNaN) {
  // The paper's layout at level 4 of 128^3; a sample inside a refined cell.
  const ref::TimeSeries s = ref::driftingBlobs(128, 1);
  ref::TimeVaryingOptions o{4};
  o.paperLayout = true;
  const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(s, ref::transferFunction("gray"), o);
  PrecisionProfile unfolded = *findProfile("llvmpipe");
  unfolded.foldsMultiplyByConstantZero = false;
  const TimeVaryingDecoderEmu folded(tex, ref::DecoderVariant::Literal, *findProfile("llvmpipe")),
      nan(tex, ref::DecoderVariant::Literal, unfolded);
  int refinedSamples = 0;
  for (int i = 0; i < 128 && refinedSamples < 50; ++i) {
    const glm::vec3 p((i + 0.5f) / 128, 0.5f, 0.4f);
    const DecodedSample a = folded.decode(0, p), b = nan.decode(0, p);
    if (!a.refined) continue;
    ++refinedSamples;
    EXPECT_EQ(b.refinementTexel, (std::array<int, 3>{0, 0, 0}));  // NaN coordinates select texel 0
    // Folded: the refinement coordinate is c.xyz + p, i.e. the block origin shifted by p.
    const auto addr = ref::addressOfVoxel(tex, 0, i, 64, static_cast<int>(0.4f * 128));
    EXPECT_NE(a.refinementTexel, addr.refinementTexel);
  }
  EXPECT_GT(refinedSamples, 0);
}

}  // namespace
}  // namespace voxref::emu
