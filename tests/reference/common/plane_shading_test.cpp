#include "reference/common/plane_shading.h"

#include <cmath>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

PlaneFrame axisFrame(int n) {
  const double h = 1.0 / 8;
  return explicitFrame({0, 0, 0}, {h, 0, 0}, {0, h, 0}, {0, 0, h}, n, n, n);
}

SampleStack stackOf(const PlaneFrame& f, double (*fn)(int, int, int)) {
  SampleStack s{f.width, f.height, f.planes, {}};
  for (int k = 0; k < f.planes; ++k)
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) s.values.push_back(fn(i, j, k));
  return s;
}

TEST(ShadePlanes, XRayIsTheRiemannSumOfTheLineIntegral) {
  const PlaneFrame f = axisFrame(8);
  const auto s = stackOf(f, [](int, int, int k) { return k * 0.25; });
  const Image img = shadePlanes(s, f, {RenderMode::XRay});
  // sum_k k/4 over k = 0..7 is 7, times the step 1/8.
  EXPECT_EQ(img.pixels[0], 7.0 / 8.0);
}

TEST(ShadePlanes, MipIsTheMaximumAndNotBelowZero) {
  const PlaneFrame f = axisFrame(8);
  const Image a =
      shadePlanes(stackOf(f, [](int i, int, int k) { return i == 3 && k == 5 ? 0.75 : 0.125; }), f, {RenderMode::Mip});
  EXPECT_EQ(a.pixels[3], 0.75);
  EXPECT_EQ(a.pixels[2], 0.125);
  const Image b = shadePlanes(stackOf(f, [](int, int, int) { return -1.0; }), f, {RenderMode::Mip});
  EXPECT_EQ(b.pixels[0], 0.0);
}

TEST(ShadePlanes, IsoHitsTheFirstCrossingWithAHeadOnNormal) {
  // value = k / 8 grows along the view direction: the gradient is parallel to dz, so the
  // Lambert term is 1 and the pixel is ambient + diffuse = 1.
  const PlaneFrame f = axisFrame(8);
  const Image img = shadePlanes(stackOf(f, [](int, int, int k) { return k / 8.0; }), f, {RenderMode::Iso, 0.3});
  EXPECT_DOUBLE_EQ(img.pixels[0], 1.0);
  // value = (i + k) / 8: the gradient is (1, 0, 1) / |.| in world space, 45 degrees from the
  // view direction, so the Lambert term is 1/sqrt(2) (central differences are exact on a linear field).
  const Image tilted =
      shadePlanes(stackOf(f, [](int i, int, int k) { return (i + k) / 8.0; }), f, {RenderMode::Iso, 0.3, 0.15});
  EXPECT_NEAR(tilted.pixels[0], 0.15 + 0.85 * std::sqrt(0.5), 1e-15);
  // No crossing: background.
  const Image none = shadePlanes(stackOf(f, [](int, int, int) { return 0.1; }), f, {RenderMode::Iso, 0.3});
  EXPECT_EQ(none.pixels[0], 0.0);
}

TEST(ShadePlanes, RejectsAMismatchedStack) {
  const PlaneFrame f = axisFrame(8);
  SampleStack s{8, 8, 7, std::vector<double>(8 * 8 * 7)};
  EXPECT_THROW(shadePlanes(s, f, {}), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
