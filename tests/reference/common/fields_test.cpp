#include "reference/common/fields.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(GaussianBuckyball, VerticesAreATruncatedIcosahedron) {
  // C60: 60 vertices on a sphere, 90 edges of equal length (2 in these coordinates), each vertex
  // on three of them.
  const auto v = buckyballVertices();
  ASSERT_EQ(v.size(), 60u);
  const double radius = distance(v[0], {0, 0, 0});
  int edges = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_NEAR(distance(v[i], {0, 0, 0}), radius, 1e-12);
    int neighbours = 0;
    for (std::size_t j = 0; j < v.size(); ++j) {
      if (i == j) continue;
      const double d = distance(v[i], v[j]);
      EXPECT_GT(d, 2.0 - 1e-9) << "no two vertices closer than an edge";
      if (d < 2.0 + 1e-9) ++neighbours;
    }
    EXPECT_EQ(neighbours, 3);
    edges += neighbours;
  }
  EXPECT_EQ(edges / 2, 90);
}

TEST(GaussianBuckyball, AtomsAreBrightAndTheCentreIsEmpty) {
  const Field f = analyticField("gaussian_buckyball");
  EXPECT_LT(f(0.5, 0.5, 0.5), 1e-6);
  const auto v = buckyballVertices();
  const double scale = 0.35 / distance(v[0], {0, 0, 0});
  EXPECT_GT(f(0.5 + scale * v[7][0], 0.5 + scale * v[7][1], 0.5 + scale * v[7][2]), 0.99);
  const Volume<std::uint8_t> s = sampleFieldU8(f, {17, 17, 17});
  EXPECT_EQ(s.at(8, 8, 8), 0);
}

TEST(GaussianBuckyball, SlicesSampledFastEqualTheWholeSum) {
  const Field f = analyticField("gaussian_buckyball");
  for (const Dims3& d : {Dims3{129, 129, 129}, Dims3{40, 23, 31}, Dims3{1, 1, 1}}) {
    const Volume<std::uint8_t> want = sampleFieldU8(f, d);
    std::vector<std::uint8_t> slice(static_cast<std::size_t>(d[0]) * static_cast<std::size_t>(d[1]));
    int bright = 0;
    for (int z = 0; z < d[2]; ++z) {
      sampleGaussianBuckyballSliceU8(d, z, slice.data());
      for (int y = 0; y < d[1]; ++y)
        for (int x = 0; x < d[0]; ++x) {
          const std::uint8_t got = slice[static_cast<std::size_t>(x + d[0] * y)];
          ASSERT_EQ(got, want.at(x, y, z)) << x << " " << y << " " << z << " of " << dimsText(d);
          bright += got > 128 ? 1 : 0;
        }
    }
    if (d[0] > 1) {
      EXPECT_GT(bright, 0);
    }
  }
}

}  // namespace
}  // namespace voxref::ref
