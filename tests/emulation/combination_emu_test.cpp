#include "emulation/combination_emu.h"

#include <bit>

#include <gtest/gtest.h>

#include "reference/common/fields.h"
#include "reference/sparsegrid/combination.h"

namespace voxref::emu {
namespace {

TEST(CombinationTexCoord, NodesLandOnTexelCentres) {
  EXPECT_EQ(combinationTexCoord(0.5f, 2, 8), 0.3125f);      // (0.5 * 4 + 0.5) / 8 exactly
  EXPECT_EQ(combinationTexCoord(1.0f, 3, 9), 8.5f / 9.0f);  // exact sizing: one rounding
}

TEST(EmulateCombination, ConstantDataIsExactInFloat) {
  // Level 1: one grid, n+ = 1; R32F texels 0.5 and a float32 framebuffer: every sample inside the
  // cube is exactly 0.5 (weights sum to 1 and every lerp of equal values is exact), 0 outside.
  const ref::Field half{"half", [](double, double, double) { return 0.5; }};
  const ref::Combination c(ref::SparseGrid::fromField({1, true}, half));
  const auto textures =
      ref::buildCombinationTextures(c, {ref::TexelFormat::R32F, ref::TextureSizing::Exact, ref::ScalingPolicy::Scaled});
  const ref::PlaneFrame frame = ref::orbitFrame(30, 20, 16, 16, 8);
  const auto out = emulateCombination(textures, frame, {}, ref::FramebufferFormat::RGBA32F, *findProfile("llvmpipe"));
  int inside = 0;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const glm::dvec3 p = frame.sample(i, j, k);
        const bool in = p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1 && p.z >= 0 && p.z <= 1;
        inside += in;
        ASSERT_EQ(std::bit_cast<float>(out.planes.codes[i + 16 * (j + 16 * k)]), in ? 0.5f : 0.0f);
      }
  EXPECT_GT(inside, 100);
  EXPECT_EQ(out.unmodelledCount, 0u);
}

TEST(EmulateCombination, SameBitsForEveryThreadCount) {
  const ref::Combination c(ref::SparseGrid::fromField({4, true}, ref::analyticField("gaussian_blobs")));
  const auto textures = ref::buildCombinationTextures(c, {});
  const ref::PlaneFrame frame = ref::orbitFrame(10, 40, 24, 20, 12);
  const auto one =
      emulateCombination(textures, frame, {}, ref::FramebufferFormat::RGBA8, *findProfile("softpipe"), {false, 1});
  for (int threads : {2, 3, 7})
    EXPECT_EQ(emulateCombination(textures, frame, {}, ref::FramebufferFormat::RGBA8, *findProfile("softpipe"),
                                 {false, threads})
                  .planes.codes,
              one.planes.codes);
}

TEST(CombinationEffects, OnlyWhatTheStateCallsFor) {
  const ref::Combination c(ref::SparseGrid::fromField({3, true}, ref::analyticField("gaussian_blobs")));
  auto has = [](const std::vector<Effect>& e, Effect x) { return std::find(e.begin(), e.end(), x) != e.end(); };
  const auto padded = ref::buildCombinationTextures(
      c, {ref::TexelFormat::R32F, ref::TextureSizing::Padded, ref::ScalingPolicy::Scaled});
  const auto exact =
      ref::buildCombinationTextures(c, {ref::TexelFormat::R32F, ref::TextureSizing::Exact, ref::ScalingPolicy::Scaled});
  const auto& lp = *findProfile("llvmpipe");
  const auto e32 = combinationEffects(padded, {}, ref::FramebufferFormat::RGBA32F, lp, {}, 8, 8);
  EXPECT_FALSE(has(e32, Effect::AddressDivision));  // power-of-two extents: the division is exact
  EXPECT_FALSE(has(e32, Effect::OutputUnorm8));     // a float32 framebuffer has no clamp or quantization
  EXPECT_FALSE(has(e32, Effect::BlendSaturatingPerPass));
  EXPECT_TRUE(has(e32, Effect::BlendFloat32));
  EXPECT_TRUE(
      has(combinationEffects(exact, {}, ref::FramebufferFormat::RGBA32F, lp, {}, 8, 8), Effect::AddressDivision));
  const auto e8 = combinationEffects(padded, {}, ref::FramebufferFormat::RGBA8, lp, {}, 8, 8);
  EXPECT_TRUE(has(e8, Effect::OutputUnorm8));
  EXPECT_TRUE(has(e8, Effect::BlendSaturatingPerPass));
}

}  // namespace
}  // namespace voxref::emu
