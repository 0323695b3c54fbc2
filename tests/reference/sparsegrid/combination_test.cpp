#include "reference/sparsegrid/combination.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "reference/common/fields.h"

namespace voxref::ref {
namespace {

TEST(CombinationGridShapes, CountsMatchEquation13AndTable2) {
  // Table 2: 31, 46, 64, 85, 109, 136, 166 grids for levels 5..11.
  const int paper[] = {31, 46, 64, 85, 109, 136, 166};
  for (int n = 5; n <= 11; ++n) EXPECT_EQ(combinationGridShapes(n).size(), static_cast<std::size_t>(paper[n - 5]));
  for (int n = 1; n <= 12; ++n)
    EXPECT_EQ(combinationGridShapes(n).size(), static_cast<std::size_t>(3 * n * (n - 1) / 2 + 1));
}

TEST(CombinationGridShapes, PositiveCountIsNinetyOneAtLevelTen) {
  // Section 6: "For a level 10 sparse grid, 91 of 136 functions contribute positive data".
  int positive = 0;
  for (const auto& s : combinationGridShapes(10)) positive += s.coefficient > 0;
  EXPECT_EQ(positive, 91);
  // Coefficients: +1 for |l| = n+2 and n, -2 for |l| = n+1; positives come first.
  const auto shapes = combinationGridShapes(4);
  bool seenNegative = false;
  for (const auto& s : shapes) {
    const int sum = s.levels[0] + s.levels[1] + s.levels[2];
    EXPECT_EQ(s.coefficient, sum == 5 ? -2 : 1);
    if (s.coefficient < 0) seenNegative = true;
    EXPECT_FALSE(seenNegative && s.coefficient > 0);
  }
}

// Exact arithmetic says combination == direct interpolation. With dyadic data and dyadic query
// points every operation of both is exact in double, so they must agree bit for bit.
TEST(Combination, EqualsDirectInterpolationBitForBitOnDyadicData) {
  for (bool boundary : {false, true}) {
    const SparseGrid g = SparseGrid::fromField({4, boundary}, analyticField("tent_product"));
    const Combination c(g);
    for (int z = 0; z <= 32; z += 3)
      for (int y = 0; y <= 32; ++y)
        for (int x = 0; x <= 32; ++x) {
          const glm::dvec3 p{x / 32.0, y / 32.0, z / 32.0};
          const ValueGradient a = g.valueGradient(p), b = c.valueGradient(p);
          ASSERT_EQ(a.value, b.value) << x << " " << y << " " << z;
          ASSERT_EQ(a.gradient, b.gradient) << x << " " << y << " " << z;
        }
  }
}

// On general data both round. Bound (Higham, Accuracy and Stability, eq. 3.5 and 4.3): a
// trilinear lerp chain is a convex combination with 3 levels of at most 4 roundings each, so
// |error| <= 12 u M_g per grid (M_g = max |node value|); the signed sum of G grids adds
// gamma_G * sum |c_g| M_g. Direct interpolation: each of T terms has 4 roundings and the sum
// gamma_T * sum |terms| <= gamma_T * T * max|surplus|. u = 2^-53.
TEST(Combination, AgreesWithDirectInterpolationWithinTheRoundingBound) {
  const SparseGrid g = SparseGrid::fromField({6, true}, analyticField("hydrogen_orbital"));
  const Combination c(g);
  const double u = std::ldexp(1.0, -53);
  double sumCM = 0.0;
  for (const ComponentGrid& grid : c.grids()) {
    double m = 0.0;
    for (double v : grid.values.data()) m = std::max(m, std::fabs(v));
    sumCM += std::abs(grid.coefficient) * m;
  }
  double maxSurplus = 0.0, terms = 0.0;
  for (double s : g.surpluses()) maxSurplus = std::max(maxSurplus, std::fabs(s));
  for (const Subspace& s : g.subspaces().subspaces())
    terms += (s.levels[0] == 0 ? 2 : 1) * (s.levels[1] == 0 ? 2 : 1) * (s.levels[2] == 0 ? 2 : 1);
  const double gridCount = static_cast<double>(c.grids().size());
  const double bound = (12 * u + gridCount * u) * sumCM + (4 + terms) * u * terms * maxSurplus;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coord(0.0, 1.0);
  double worst = 0.0;
  for (int t = 0; t < 2000; ++t) {
    const glm::dvec3 p{coord(rng), coord(rng), coord(rng)};
    worst = std::max(worst, std::fabs(g.value(p) - c.value(p)));
  }
  EXPECT_LE(worst, bound);
  EXPECT_GT(worst, 0.0);  // the test would be vacuous if both were exact here
}

TEST(Trilinear, ValueAloneIsBitIdenticalToValueWithGradient) {
  const Combination c(SparseGrid::fromField({5, true}, analyticField("hydrogen_orbital")));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(0.0, 1.0);
  for (int t = 0; t < 500; ++t) {
    const glm::dvec3 p{coord(rng), coord(rng), coord(rng)};
    for (const ComponentGrid& g : c.grids())
      ASSERT_EQ(trilinearValue(g.values, g.levels, p), trilinear(g.values, g.levels, p).value);
    ASSERT_EQ(c.value(p), c.valueGradient(p).value);
  }
}

TEST(Combination, ComponentGridsHoldTheSparseGridsNodalValues) {
  const Field f = analyticField("gaussian_blobs");
  const SparseGrid g = SparseGrid::fromField({5, true}, f);
  const Combination c(g);
  EXPECT_EQ(c.positiveCount(), 15 + 6);  // |l| = 7: C(6,2) = 15 grids; |l| = 5: C(4,2) = 6
  for (const ComponentGrid& grid : c.grids()) {
    const auto& l = grid.levels;
    const int a = (1 << l[0]) / 2, b = 1 << l[1], cc = 0;  // an interior, a boundary node
    EXPECT_EQ(grid.values.at(a, b, cc), f(a / double(1 << l[0]), b / double(1 << l[1]), 0.0));
  }
}

TEST(Combination, ZeroBoundaryGridsAreZeroOnTheBoundary) {
  const Combination c(SparseGrid::fromField({4, false}, analyticField("constant_one")));
  for (const ComponentGrid& grid : c.grids()) {
    EXPECT_EQ(grid.values.at(0, 1, 1), 0.0);
    EXPECT_EQ(grid.values.at(1, 1, 1), 1.0);
  }
}

}  // namespace
}  // namespace voxref::ref
