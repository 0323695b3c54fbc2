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

}  // namespace
}  // namespace voxref::ref
