#include "reference/sparsegrid/sparse_grid.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "reference/common/fields.h"

namespace voxref::ref {
namespace {

TEST(HatTerms, RightSidedSlopeConvention) {
  // Level 2 hats: centres 1/4 and 3/4, slope +-4.
  const HatTerms atNode = hatTermsAt(2, 0.25);
  ASSERT_EQ(atNode.count, 1);
  EXPECT_EQ(atNode.terms[0].index, 0);
  EXPECT_EQ(atNode.terms[0].value, 1.0);
  EXPECT_EQ(atNode.terms[0].slope, -4.0);      // right of the kink
  const HatTerms atHalf = hatTermsAt(2, 0.5);  // left end of hat 1's support
  EXPECT_EQ(atHalf.terms[0].index, 1);
  EXPECT_EQ(atHalf.terms[0].value, 0.0);
  EXPECT_EQ(atHalf.terms[0].slope, 4.0);
  const HatTerms atOne = hatTermsAt(2, 1.0);  // x = 1: the cell to the left
  EXPECT_EQ(atOne.terms[0].index, 1);
  EXPECT_EQ(atOne.terms[0].slope, -4.0);
  const HatTerms boundary = hatTermsAt(0, 0.25);
  ASSERT_EQ(boundary.count, 2);
  EXPECT_EQ(boundary.terms[0].value, 0.75);
  EXPECT_EQ(boundary.terms[1].value, 0.25);
}

TEST(SparseGrid, InterpolatesItsNodalValuesExactly) {
  // Dyadic data: every operation is exact, so interpolation at a node returns the node's value.
  for (bool boundary : {false, true}) {
    const SparseGrid g = SparseGrid::fromField({4, boundary}, analyticField("tent_product"));
    const int n = 4;
    for (const Subspace& s : g.subspaces().subspaces())
      for (int k = 0; k < s.count[2]; ++k)
        for (int j = 0; j < s.count[1]; ++j)
          for (int i = 0; i < s.count[0]; ++i) {
            const glm::dvec3 x{std::ldexp(double(latticeCoordinate(n, s.levels[0], i)), -n),
                               std::ldexp(double(latticeCoordinate(n, s.levels[1], j)), -n),
                               std::ldexp(double(latticeCoordinate(n, s.levels[2], k)), -n)};
            ASSERT_EQ(g.value(x), g.nodalValues()[s.offset + i + s.count[0] * (j + s.count[1] * k)]);
          }
  }
}

TEST(SparseGrid, ReproducesLinearFunctionsWithBoundaryPoints) {
  // A trilinear function lives in the boundary level: every other surplus is zero, and the
  // interpolant and its gradient are the function's own.
  const Field linear{"linear", [](double x, double y, double z) { return 0.25 + 0.5 * x - 0.25 * y + 0.125 * z; }};
  const SparseGrid g = SparseGrid::fromField({5, true}, linear);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> lattice(0, 1024);
  for (int t = 0; t < 200; ++t) {
    const glm::dvec3 x{lattice(rng) / 1024.0, lattice(rng) / 1024.0, lattice(rng) / 1024.0};
    const ValueGradient vg = g.valueGradient(x);
    EXPECT_EQ(vg.value, linear(x.x, x.y, x.z));
    EXPECT_EQ(vg.gradient, glm::dvec3(0.5, -0.25, 0.125));
  }
}

TEST(SparseGrid, LevelTwelveWorksWithoutAFullGrid) {
  // A level-12 full grid would hold 4097^3 = 68.8e9 values (550 GB); the sparse grid has
  // fewer than 10^7 points and is built and evaluated directly.
  const Field f = analyticField("gaussian_blobs");
  const SparseGrid g = SparseGrid::fromField({12, true}, f);
  EXPECT_LT(g.subspaces().pointCount(), std::size_t{10'000'000});
  // At a node the interpolant equals the sample up to rounding. Bound: each surplus carries at
  // most E_h = 36 updates x 3 operations x 8 x 2^-53 (3 axes x 12 levels, operands below 8); the
  // T hat products (T = sum over subspaces of 2^(number of boundary-level axes), each hat <= 1)
  // add E_h each, and their summation at most (T + 3) * 2^-53 relative to T terms below 8.
  double terms = 0.0;
  for (const Subspace& s : g.subspaces().subspaces())
    terms += (s.levels[0] == 0 ? 2 : 1) * (s.levels[1] == 0 ? 2 : 1) * (s.levels[2] == 0 ? 2 : 1);
  const double eps = std::ldexp(1.0, -53), hierarchizationError = 36 * 3 * 8 * eps;
  const double bound = terms * hierarchizationError + terms * (terms + 3) * 8 * eps;
  const glm::dvec3 node{0.5, 0.0, 1.0 / 4096};  // levels (1, 0, 12): max(.,1) sums to 14 = n + 2
  ASSERT_TRUE(g.subspaces().pointAt({2048, 0, 1}).has_value());
  EXPECT_NEAR(g.value(node), f(node.x, node.y, node.z), bound);
}

TEST(SparseGrid, NodalAtRejectsPointsOutsideTheGrid) {
  const SparseGrid g = SparseGrid::fromField({3, true}, analyticField("zero"));
  EXPECT_THROW(g.nodalAt({1, 1, 1}), std::out_of_range);  // (3,3,3): sum 9 > 5
  EXPECT_EQ(g.nodalAt({0, 8, 4}), 0.0);
  EXPECT_THROW(SparseGrid::fromNodalValues({3, true}, std::vector<double>(5)), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
