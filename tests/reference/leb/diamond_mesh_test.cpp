#include "reference/leb/diamond_mesh.h"

#include "tests/reference/leb/conforming_mesh.h"
#include "tests/reference/leb/grid_points.h"

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

// Paths name tetrahedra: over many meshes of one grid, a path always comes with the same corners
// (in the same order), its creator and split vertex are what bisection gives, the leaves of a mesh
// come in rising path order, and leafOnPath finds each leaf again from its path alone (and the leaf
// above a path that goes deeper than the mesh).
TEST(DiamondMesh, LeafPathsNameOneTetrahedronAndRiseInVisitingOrder) {
  const LebGrid g = makeLebGrid(3);
  std::mt19937 rng(1999);
  std::uniform_int_distribution<int> coord(0, g.side());
  std::map<std::uint64_t, Tetrahedron> named;
  DiamondMesh mesh(g);
  for (int step = 0; step < 300; ++step) {
    const GridPoint p{coord(rng), coord(rng), coord(rng)};
    if (isRootCorner(g, p)) continue;
    if (rng() % 3 == 0) {
      if (mesh.canMerge(p)) mesh.merge(p);
    } else {
      mesh.split(p);
    }
    std::uint64_t previous = 0;
    std::size_t count = 0;
    mesh.forEachLeafVisit([&](const LeafVisit& v) {
      if (count++ > 0) {
        EXPECT_LT(previous, v.path);
      }
      previous = v.path;
      const auto [it, added] = named.try_emplace(v.path, v.t);
      EXPECT_EQ(it->second.v, v.t.v) << "path " << v.path << " named two tetrahedra";
      GridPoint m;
      EXPECT_EQ(tetrahedronSplitVertex(v.t, m), v.hasSplitVertex);
      if (v.hasSplitVertex) {
        EXPECT_EQ(m, v.splitVertex);
        EXPECT_FALSE(mesh.isSplit(m));
      }
      if (v.creator[0] >= 0) {
        EXPECT_TRUE(mesh.isSplit(v.creator));
      }
      // What the traversal carries is what the corners say.
      EXPECT_EQ(v.longest, longestEdge(v.t));
      if (v.creatorSlot >= 0) {
        EXPECT_EQ(v.t.v[static_cast<std::size_t>(v.creatorSlot)], v.creator);
      } else {
        EXPECT_LT(v.creator[0], 0);
      }
      const LeafVisit again = mesh.leafOnPath(v.path);
      EXPECT_EQ(again.path, v.path);
      EXPECT_EQ(again.t.v, v.t.v);
      EXPECT_EQ(again.creator, v.creator);
      // A path two halves further down the second half's side leads back to this leaf.
      const std::uint64_t deeper = halfLeafPath(halfLeafPath(v.path, 1), 1);
      if ((deeper & kLeafPathDepthMask) <= static_cast<std::uint64_t>(g.levelCount())) {
        EXPECT_EQ(mesh.leafOnPath(deeper).path, v.path);
      }
    });
    EXPECT_EQ(count, mesh.leafTetrahedra().size());
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(named.size(), 500u);
  EXPECT_THROW(mesh.leafOnPath(std::uint64_t{7} << 61), std::invalid_argument);  // no seventh root
  EXPECT_THROW(mesh.leafOnPath(rootLeafPath(0) | 40), std::invalid_argument);    // deeper than the grid
}

// toHalf, which the traversals use, makes the halves bisectTetrahedron makes (cut at the midpoint
// of the longest edge found from the corners), in the same corner order, with the visit's fields
// what visitOf finds for them: over every tetrahedron of a grid down to the finest level. Its
// longest edge is found among the corners other than the creator (longestEdgeOfHalf); nine levels
// of halves are three times every shape of the hierarchy.
TEST(DiamondMesh, AVisitsHalvesAreTheHalvesOfBisection) {
  const LebGrid g = makeLebGrid(3);
  std::vector<LeafVisit> pending;
  const std::array<Tetrahedron, 6> roots = rootTetrahedra(g);
  for (int r = 0; r < 6; ++r)
    pending.push_back(visitOf(roots[static_cast<std::size_t>(r)], {-1, -1, -1}, rootLeafPath(r)));
  std::size_t halved = 0;
  while (!pending.empty()) {
    const LeafVisit v = pending.back();
    pending.pop_back();
    if (!v.hasSplitVertex) continue;
    const std::array<Tetrahedron, 2> halves = bisectTetrahedron(v.t, v.splitVertex);
    for (int h = 0; h < 2; ++h) {
      LeafVisit half = v;
      toHalf(half, h);
      ASSERT_EQ(half.t.v, halves[static_cast<std::size_t>(h)].v) << "half " << h << " of path " << v.path;
      const LeafVisit found = visitOf(half.t, v.splitVertex, halfLeafPath(v.path, h));
      EXPECT_EQ(half.path, found.path);
      EXPECT_EQ(half.creator, found.creator);
      EXPECT_EQ(half.creatorSlot, found.creatorSlot);
      EXPECT_GE(half.creatorSlot, 0);
      EXPECT_EQ(half.longest, found.longest);
      EXPECT_EQ(half.hasSplitVertex, found.hasSplitVertex);
      EXPECT_EQ(half.splitVertex, found.splitVertex);
      pending.push_back(half);
      ++halved;
    }
  }
  EXPECT_EQ(halved, 2 * (6u * 512u - 6u));  // every split makes two of the 6 per cell from 6 roots
}

TEST(DiamondMesh, FullRefinementHasSixTetrahedraPerCell) {
  const LebGrid g = makeLebGrid(2);
  const DiamondMesh mesh = test_support::fullyRefined(g);
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
