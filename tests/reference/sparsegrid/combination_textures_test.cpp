#include "reference/sparsegrid/combination_textures.h"

#include <cmath>

#include <gtest/gtest.h>

#include "reference/common/fields.h"
#include "reference/common/texel_format.h"

namespace voxref::ref {
namespace {

TEST(CombinationTextures, ScaledTexelsHoldFactorTimesDataOverNPlus) {
  const Combination c(SparseGrid::fromField({3, true}, analyticField("gaussian_blobs")));
  const CombinationTextures t =
      buildCombinationTextures(c, {TexelFormat::R32F, TextureSizing::Padded, ScalingPolicy::Scaled});
  ASSERT_EQ(t.textures.size(), c.grids().size());
  EXPECT_EQ(t.positiveCount, 6 + 1);  // |l| = 5 with l_d >= 1: C(4,2) = 6 grids; |l| = 3: 1
  EXPECT_EQ(t.readbackScale, t.positiveCount);
  for (std::size_t i = 0; i < c.grids().size(); ++i) {
    const ComponentGrid& g = c.grids()[i];
    const GridTexture& tex = t.textures[i];
    for (int a = 0; a < 3; ++a) EXPECT_EQ(tex.dims[a], 2 << g.levels[a]);  // 2^(l+1)
    const double factor = g.coefficient < 0 ? 2.0 : 1.0;
    const int x = 1 << g.levels[0], y = 0, z = 1;
    EXPECT_EQ(tex.codes[x + tex.dims[0] * (y + tex.dims[1] * z)],
              encodeTexel(TexelFormat::R32F, factor * g.values.at(x, y, z) / t.positiveCount));
    EXPECT_EQ(tex.codes.back(), encodeTexel(TexelFormat::R32F, 0.0));  // padding
  }
}

TEST(CombinationTextures, PassesAddPositivesThenSubtractNegatives) {
  const Combination c(SparseGrid::fromField({4, true}, analyticField("gaussian_blobs")));
  const auto scaled = buildCombinationTextures(c, {TexelFormat::R16, TextureSizing::Exact, ScalingPolicy::Scaled});
  const auto unscaled = buildCombinationTextures(c, {TexelFormat::R16, TextureSizing::Exact, ScalingPolicy::Unscaled});
  int negatives = 0;
  for (const auto& g : c.grids()) negatives += g.coefficient < 0;
  EXPECT_EQ(scaled.passes.size(), c.grids().size());
  EXPECT_EQ(unscaled.passes.size(), c.grids().size() + negatives);  // negatives drawn twice
  EXPECT_EQ(unscaled.readbackScale, 1.0);
  for (std::size_t i = 0; i < scaled.passes.size(); ++i) {
    const bool positive = c.grids()[scaled.passes[i].texture].coefficient > 0;
    EXPECT_EQ(scaled.passes[i].equation, positive ? BlendEquation::FuncAdd : BlendEquation::FuncReverseSubtract);
    EXPECT_EQ(positive, static_cast<int>(i) < scaled.positiveCount);
  }
  for (const auto& tex : scaled.textures)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(tex.dims[a], (1 << tex.levels[a]) + 1);
}

TEST(TextureCoordinate, NodesSitAtTexelCentres) {
  // The paper's bias 1/(4 * 2^l) on s/2 puts node a at texel a's centre in a 2^(l+1) texture.
  for (int l = 1; l <= 10; ++l)
    for (int a = 0; a <= (1 << l); ++a) {
      const double p = std::ldexp(static_cast<double>(a), -l);
      const int padded = textureExtent(l, TextureSizing::Padded), exact = textureExtent(l, TextureSizing::Exact);
      EXPECT_EQ(textureCoordinate(p, l, padded), 0.5 * p + 1.0 / (4 << l));
      EXPECT_EQ(textureCoordinate(p, l, padded) * padded, a + 0.5);
      EXPECT_NEAR(textureCoordinate(p, l, exact) * exact, a + 0.5, 1e-12);
    }
}

}  // namespace
}  // namespace voxref::ref
