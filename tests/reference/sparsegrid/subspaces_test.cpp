#include "reference/sparsegrid/subspaces.h"

#include <cstdint>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

// Independent count: the union of the nodes of all combination-technique grids
// (2^l1 + 1) x (2^l2 + 1) x (2^l3 + 1), l_d >= 1, |l| in {n, n+1, n+2}, as lattice points of
// the level-n full grid. With `interiorOnly`, boundary nodes are left out (zero boundary).
std::size_t unionOfCombinationNodes(int n, bool interiorOnly) {
  std::set<std::tuple<std::int64_t, std::int64_t, std::int64_t>> nodes;
  const std::int64_t full = std::int64_t{1} << n;
  for (int l1 = 1; l1 <= n; ++l1)
    for (int l2 = 1; l2 <= n; ++l2)
      for (int l3 = 1; l3 <= n; ++l3) {
        const int sum = l1 + l2 + l3;
        if (sum < n || sum > n + 2) continue;
        for (std::int64_t a = 0; a <= (1 << l1); ++a)
          for (std::int64_t b = 0; b <= (1 << l2); ++b)
            for (std::int64_t c = 0; c <= (1 << l3); ++c) {
              const std::int64_t x = a << (n - l1), y = b << (n - l2), z = c << (n - l3);
              const bool onBoundary = x == 0 || y == 0 || z == 0 || x == full || y == full || z == full;
              if (interiorOnly && onBoundary) continue;
              nodes.emplace(x, y, z);
            }
      }
  return nodes.size();
}

TEST(SubspaceSet, PointCountEqualsTheUnionOfCombinationGridNodes) {
  for (int n = 1; n <= 7; ++n) {
    EXPECT_EQ(SubspaceSet({n, true}).pointCount(), unionOfCombinationNodes(n, false)) << "level " << n;
    EXPECT_EQ(SubspaceSet({n, false}).pointCount(), unionOfCombinationNodes(n, true)) << "level " << n;
  }
}

TEST(SubspaceSet, ZeroBoundaryCountMatchesClosedForm) {
  // Level i of the sparse grid has i(i+1)/2 subspaces of 2^(i-1) points each (section 2, eq. 12).
  for (int n = 1; n <= 12; ++n) {
    std::size_t expected = 0;
    for (int i = 1; i <= n; ++i) expected += static_cast<std::size_t>(i * (i + 1) / 2) << (i - 1);
    EXPECT_EQ(SubspaceSet({n, false}).pointCount(), expected) << n;
  }
}

TEST(SubspaceSet, EveryPointIsAddressableByItsLatticeCoordinates) {
  for (bool boundary : {false, true}) {
    const SubspaceSet set({5, boundary});
    std::set<std::size_t> seen;
    for (const Subspace& s : set.subspaces())
      for (int k = 0; k < s.count[2]; ++k)
        for (int j = 0; j < s.count[1]; ++j)
          for (int i = 0; i < s.count[0]; ++i) {
            const auto p = set.pointAt({latticeCoordinate(5, s.levels[0], i), latticeCoordinate(5, s.levels[1], j),
                                        latticeCoordinate(5, s.levels[2], k)});
            ASSERT_TRUE(p.has_value());
            EXPECT_EQ(*p, s.offset + i + s.count[0] * (j + s.count[1] * k));
            seen.insert(*p);
          }
    EXPECT_EQ(seen.size(), set.pointCount());
    EXPECT_FALSE(set.pointAt({33, 0, 0}).has_value());  // outside the lattice
  }
  // (5,5,1) sums to 11 > 7: a full-grid point that the sparse grid does not hold.
  EXPECT_FALSE(SubspaceSet({5, true}).pointAt({1, 1, 16}).has_value());
}

TEST(AxisPoint, InvertsLatticeCoordinate) {
  for (int n = 1; n <= 12; ++n)
    for (int level = 0; level <= n; ++level)
      for (int j = 0; j < pointsOnLevel(level); ++j) {
        const AxisPoint p = axisPointOf(n, latticeCoordinate(n, level, j));
        ASSERT_EQ(p.level, level);
        ASSERT_EQ(p.index, j);
      }
}

TEST(SubspaceSet, RejectsLevelsOutsideOneToTwelve) {
  EXPECT_THROW(SubspaceSet({0, true}), std::invalid_argument);
  EXPECT_THROW(SubspaceSet({13, false}), std::invalid_argument);
  EXPECT_NO_THROW(SubspaceSet({12, true}));
}

}  // namespace
}  // namespace voxref::ref
