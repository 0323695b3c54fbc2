#include "reference/leb/gradients.h"

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

TEST(QuantizedGradients, ClosedFormsOfLinearFields) {
  // v = 2x + y: gradient (2, 1, 0) / sqrt(5) everywhere (the one-sided differences on the faces
  // of a linear field are exact too): round(127 * 2 / sqrt(5)) = 114, round(127 / sqrt(5)) = 57.
  Volume<std::uint16_t> v({5, 4, 3});
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 5; ++x) v.at(x, y, z) = static_cast<std::uint16_t>(2 * x + y);
  const auto g = quantizedGradients(v);
  for (std::size_t i = 0; i < g.size(); i += 3) {
    EXPECT_EQ(g[i], 114);
    EXPECT_EQ(g[i + 1], 57);
    EXPECT_EQ(g[i + 2], 0);
  }
}

TEST(QuantizedGradients, ZeroForConstantAndFlatAxes) {
  const auto g = quantizedGradients(Volume<std::uint16_t>({3, 3, 3}, 9));
  for (std::int8_t c : g) EXPECT_EQ(c, 0);
  Volume<std::uint16_t> line({4, 1, 1});
  for (int x = 0; x < 4; ++x) line.at(x, 0, 0) = static_cast<std::uint16_t>(10 - x);
  const auto h = quantizedGradients(line);
  EXPECT_EQ(h[0], -127);
  EXPECT_EQ(h[1], 0);
  EXPECT_EQ(h[2], 0);
}

TEST(QuantizedGradients, CentralDifferencesInside) {
  // v = x^2 along x: at x = 2 the central difference (9 - 1) / 2 = 4, with y's (0) -> (127, 0, 0);
  // mixing in y = 4 (constant 4 per step) gives (4, 4, 0) / sqrt(32): round(127 / sqrt 2) = 90.
  Volume<std::uint16_t> v({5, 5, 1});
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x) v.at(x, y, 0) = static_cast<std::uint16_t>(x * x + 4 * y);
  const auto g = quantizedGradients(v);
  const std::size_t at = 3 * v.index(2, 2, 0);
  EXPECT_EQ(g[at], 90);
  EXPECT_EQ(g[at + 1], 90);
}

TEST(DiffusedGradients, ALinearRampIsAFixedPointOfTheDiffusion) {
  // v = 2x + 3y + z: every central and one-sided difference is (2, 3, 1), so diffusion (no flux
  // through the faces) changes nothing, and each gradient is round(127 (2, 3, 1) / sqrt 14) =
  // (68, 102, 34).
  Volume<std::uint16_t> v({6, 5, 4});
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 5; ++y)
      for (int x = 0; x < 6; ++x) v.at(x, y, z) = static_cast<std::uint16_t>(2 * x + 3 * y + z);
  const auto g = diffusedQuantizedGradients(v, 5);
  EXPECT_EQ(g, quantizedGradients(v));
  for (std::size_t i = 0; i < v.data().size(); ++i) {
    EXPECT_EQ(g[3 * i], 68);
    EXPECT_EQ(g[3 * i + 1], 102);
    EXPECT_EQ(g[3 * i + 2], 34);
  }
}

TEST(DiffusedGradients, OneStepFillsTheDegenerateGradientsBesideASpike) {
  // 5x1x1 samples 0 0 8 0 0: central differences gx = 0, 4, 0, -4, 0 (one-sided at the ends). One
  // step, two neighbours on x and none on y, z: 0 + 4/6, 4 - 8/6, 0 + 0, -4 + 8/6, 0 - 4/6, so the
  // zero gradients at both ends (degenerate for shading) become +-127; the spike's own stays 0.
  const Volume<std::uint16_t> v({5, 1, 1}, std::vector<std::uint16_t>{0, 0, 8, 0, 0});
  const auto raw = quantizedGradients(v), one = diffusedQuantizedGradients(v, 1);
  const int rawX[5] = {0, 127, 0, -127, 0}, oneX[5] = {127, 127, 0, -127, -127};
  for (std::size_t x = 0; x < 5; ++x) {
    EXPECT_EQ(raw[3 * x], rawX[x]) << x;
    EXPECT_EQ(one[3 * x], oneX[x]) << x;
    EXPECT_EQ(one[3 * x + 1], 0);
    EXPECT_EQ(one[3 * x + 2], 0);
  }
  EXPECT_EQ(diffusedQuantizedGradients(v, 0), raw);
}

}  // namespace
}  // namespace voxref::ref
