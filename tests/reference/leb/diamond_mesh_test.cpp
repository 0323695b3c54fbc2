#include "reference/leb/diamond_mesh.h"

#include "tests/reference/leb/conforming_mesh.h"

#include <algorithm>
#include <map>
#include <random>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

using test_support::expectConforming;

TEST(DiamondMesh, RandomSplitAndMergeSequencesStayConforming) {
  const LebGrid g = makeLebGrid(3);
  std::mt19937 rng(2004);
  std::uniform_int_distribution<int> coord(0, g.side());
  for (int run = 0; run < 20; ++run) {
    DiamondMesh mesh(g);
    expectConforming(mesh);
    EXPECT_EQ(mesh.leafTetrahedra().size(), 6u);
    for (int step = 0; step < 60; ++step) {
      const GridPoint p{coord(rng), coord(rng), coord(rng)};
      if (isRootCorner(g, p)) continue;
      if (rng() % 3 == 0) {
        if (mesh.canMerge(p)) mesh.merge(p);
      } else {
        const auto done = mesh.split(p);
        for (const GridPoint& d : done)
          for (const GridPoint& parent : diamondParents(g, d)) ASSERT_TRUE(mesh.isSplit(parent));
      }
      expectConforming(mesh);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}

TEST(DiamondMesh, FullRefinementHasSixTetrahedraPerCell) {
  const LebGrid g = makeLebGrid(2);
  DiamondMesh mesh(g);
  for (int z = 0; z <= 4; ++z)
    for (int y = 0; y <= 4; ++y)
      for (int x = 0; x <= 4; ++x)
        if (!isRootCorner(g, {x, y, z})) mesh.split({x, y, z});
  EXPECT_EQ(mesh.splitCount(), g.pointCount() - 8);
  EXPECT_EQ(mesh.leafTetrahedra().size(), 6u * 64u);
  expectConforming(mesh);
}

TEST(DiamondMesh, MergeRefusesASplitChildAndSplitBringsParents) {
  const LebGrid g = makeLebGrid(2);
  DiamondMesh mesh(g);
  const auto done = mesh.split({1, 1, 1});  // a level-3 cube centre: needs levels 0, 1, 2 first
  EXPECT_GT(done.size(), 1u);
  EXPECT_EQ(done.front(), (GridPoint{2, 2, 2}));
  EXPECT_EQ(done.back(), (GridPoint{1, 1, 1}));
  EXPECT_FALSE(mesh.canMerge({2, 2, 2}));
  EXPECT_THROW(mesh.merge({2, 2, 2}), std::logic_error);
  EXPECT_TRUE(mesh.canMerge({1, 1, 1}));
  mesh.merge({1, 1, 1});
  EXPECT_FALSE(mesh.isSplit({1, 1, 1}));
  EXPECT_THROW(mesh.split({0, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
