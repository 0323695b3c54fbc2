#include "reference/sparsegrid/hierarchize.h"

#include <cmath>

#include <gtest/gtest.h>

#include "reference/common/fields.h"
#include "reference/sparsegrid/sparse_grid.h"

namespace voxref::ref {
namespace {

// f = 64 x(1-x) y(1-y) z(1-z). In 1D the surplus of x(1-x) at a level-l point is
// f(m) - (f(m - h) + f(m + h)) / 2 = h^2 = 4^-l (the second difference of -x^2); by the tensor
// product the 3D surplus is 64 * 4^-(l1+l2+l3), and 0 on boundary levels (f vanishes there).
// All values are dyadic with few bits, so double arithmetic is exact and we compare with ==.
TEST(HierarchizeSparse, TentProductSurplusesMatchTheClosedForm) {
  for (bool boundary : {false, true}) {
    const SparseGrid g = SparseGrid::fromField({6, boundary}, analyticField("tent_product"));
    for (const Subspace& s : g.subspaces().subspaces()) {
      const bool boundaryLevel = s.levels[0] == 0 || s.levels[1] == 0 || s.levels[2] == 0;
      const double expected = boundaryLevel ? 0.0 : std::ldexp(64.0, -2 * (s.levels[0] + s.levels[1] + s.levels[2]));
      for (std::size_t p = s.offset; p < s.offset + s.size(); ++p) ASSERT_EQ(g.surpluses()[p], expected);
    }
  }
}

TEST(HierarchizeSparse, IsBitIdenticalToFullGridHierarchization) {
  const Field f = analyticField("gaussian_blobs");
  for (bool boundary : {false, true}) {
    const int n = 5, side = 33;
    Volume<double> full({side, side, side});
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) full.at(x, y, z) = f(x / 32.0, y / 32.0, z / 32.0);
    hierarchizeFullGrid(full, boundary);
    const SparseGrid g = SparseGrid::fromField({n, boundary}, f);
    for (const Subspace& s : g.subspaces().subspaces())
      for (int k = 0; k < s.count[2]; ++k)
        for (int j = 0; j < s.count[1]; ++j)
          for (int i = 0; i < s.count[0]; ++i) {
            const double expected = full.at(static_cast<int>(latticeCoordinate(n, s.levels[0], i)),
                                            static_cast<int>(latticeCoordinate(n, s.levels[1], j)),
                                            static_cast<int>(latticeCoordinate(n, s.levels[2], k)));
            ASSERT_EQ(g.surpluses()[s.offset + i + s.count[0] * (j + s.count[1] * k)], expected);
          }
  }
}

TEST(HierarchizeSparse, DehierarchizeInvertsIt) {
  const SubspaceSet set({6, true});
  const SparseGrid tent = SparseGrid::fromField({6, true}, analyticField("tent_product"));
  std::vector<double> u = tent.surpluses();
  dehierarchizeSparse(set, u);
  EXPECT_EQ(u, tent.nodalValues());  // exact on dyadic data
  const SparseGrid blobs = SparseGrid::fromField({6, true}, analyticField("gaussian_blobs"));
  u = blobs.surpluses();
  dehierarchizeSparse(set, u);
  // Bound: a point takes part in at most 3 axes x 6 levels updates each way (72 in all), each
  // rounding once per operation (3 operations) on operands below 8 in magnitude (3D surpluses of
  // data in [0,1] are bounded by 2^3): 72 * 3 * 8 * 2^-53 = 1.9e-13.
  const double bound = 72 * 3 * 8 * std::ldexp(1.0, -53);
  for (std::size_t i = 0; i < u.size(); ++i) ASSERT_NEAR(u[i], blobs.nodalValues()[i], bound);
}

TEST(HierarchizeFullGrid, RejectsGridsThatAreNotTwoToTheNPlusOne) {
  Volume<double> v({10, 10, 10});
  EXPECT_THROW(hierarchizeFullGrid(v, true), std::invalid_argument);
  std::vector<double> wrong(7);
  EXPECT_THROW(hierarchizeSparse(SubspaceSet({3, true}), wrong), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
