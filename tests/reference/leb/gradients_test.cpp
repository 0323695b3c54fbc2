#include "reference/leb/gradients.h"

#include <algorithm>
#include <cmath>

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

// The interior samples' shorter road (interiorQuantizedGradient) against the definition,
// quantizeGradient of the central differences / 2: every difference vector with components in
// [-24, 24], a lattice through the whole 8-bit range, and random 16-bit ones (the whole 8-bit cube,
// 511^3 vectors, was checked once outside the tests: no difference).
TEST(QuantizedGradients, TheInteriorRoadGivesTheDefinitionsBits) {
  auto expectSame = [](std::int32_t ex, std::int32_t ey, std::int32_t ez) {
    std::int8_t want[3], got[3];
    quantizeGradient({ex / 2.0, ey / 2.0, ez / 2.0}, want);
    interiorQuantizedGradient(ex, ey, ez, got);
    return want[0] == got[0] && want[1] == got[1] && want[2] == got[2];
  };
  int differ = 0;
  for (int ex = -24; ex <= 24; ++ex)
    for (int ey = -24; ey <= 24; ++ey)
      for (int ez = -24; ez <= 24; ++ez) differ += !expectSame(ex, ey, ez);
  for (int ex = -255; ex <= 255; ex += 6)
    for (int ey = -255; ey <= 255; ey += 6)
      for (int ez = -255; ez <= 255; ez += 6) differ += !expectSame(ex, ey, ez);
  std::uint64_t state = 0x9e3779b97f4a7c15ULL;
  auto next = [&] {  // splitmix64
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<std::int32_t>((z ^ (z >> 31)) % 131071) - 65535;
  };
  for (int i = 0; i < 200000; ++i) differ += !expectSame(next(), next(), next());
  EXPECT_EQ(differ, 0);
}

TEST(QuantizedGradients, RoundingIsLroundsHalfAwayFromZero) {
  for (double x : {0.5, 1.5, 2.5, 126.5, -0.5, -1.5, -126.5, 127.0, -127.0, 0.0, 0.49999999999999994,
                   -0.49999999999999994, std::nextafter(2.5, 0.0), std::nextafter(-2.5, 0.0), 3.7, -3.7})
    EXPECT_EQ(roundHalfAwayFromZero(x), static_cast<std::int8_t>(std::lround(x))) << x;
}

// A volume of random samples, 8 and 16 bits, with faces, edges and corners: every sample's
// gradient as the definition gives it, one sample at a time.
TEST(QuantizedGradients, EverySampleOfARandomVolumeIsTheDefinitions) {
  std::uint32_t state = 12345;
  for (const int bits : {8, 16}) {
    Volume<std::uint16_t> v({7, 5, 6});
    for (auto& s : v.data()) {
      state = state * 1664525u + 1013904223u;
      s = static_cast<std::uint16_t>((state >> 8) & ((1u << bits) - 1));
    }
    const auto g = quantizedGradients(v);
    for (int z = 0; z < 6; ++z)
      for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x) {
          std::int8_t want[3];
          quantizeGradient(centralGradient(v.data().data(), v.dims(), x, y, z), want);
          const std::size_t at = 3 * v.index(x, y, z);
          for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(g[at + c], want[c]) << bits << " bits at " << x << y << z;
        }
  }
}

// quantizedGradientsInto: the bytes of quantizedGradients on any thread count, for 8- and 16-bit
// samples, and afterBatch told a rising fraction that ends at 1.
TEST(QuantizedGradients, IntoGivesTheSameBytesOnEveryThreadCount) {
  Volume<std::uint16_t> v({13, 11, 29});
  std::uint32_t state = 99;
  for (auto& s : v.data()) {
    state = state * 1664525u + 1013904223u;
    s = static_cast<std::uint16_t>((state >> 9) & 255);
  }
  const std::vector<std::int8_t> want = quantizedGradients(v);
  const std::vector<std::uint8_t> narrow(v.data().begin(), v.data().end());
  for (const int threads : {1, 2, 3}) {
    std::vector<std::int8_t> got8(want.size(), 0), got16(want.size(), 0);
    std::vector<double> seen;
    quantizedGradientsInto(narrow.data(), v.dims(), got8.data(), threads, [&](double done) { seen.push_back(done); });
    quantizedGradientsInto(v.data().data(), v.dims(), got16.data(), threads);
    EXPECT_EQ(got8, want) << threads;
    EXPECT_EQ(got16, want) << threads;
    ASSERT_FALSE(seen.empty());
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  }
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
