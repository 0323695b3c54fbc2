// The closed forms of leb_grid.h against brute force: the root cube cut into its six tetrahedra
// around the major diagonal, every tetrahedron bisected at the midpoint of its longest edge
// (found by comparing squared lengths) until its longest edge has no grid midpoint. Nothing here
// uses the formulas under test.
#include "reference/leb/leb_grid.h"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "tests/reference/leb/grid_points.h"

namespace voxref::ref {
namespace {

using Edge = std::pair<GridPoint, GridPoint>;
Edge sorted(GridPoint a, GridPoint b) { return a < b ? Edge{a, b} : Edge{b, a}; }

struct BruteDiamond {
  std::set<Edge> splitEdges;
  std::set<int> depths;
  std::set<GridPoint> ring, parents, children;
  int tets = 0;
};

struct BruteForce {
  std::map<GridPoint, BruteDiamond> diamonds;

  explicit BruteForce(int k) {
    const int n = 1 << k;
    const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& pm : perm) {
      std::array<GridPoint, 4> t{};
      t[0] = {0, 0, 0};
      t[1] = t[0];
      t[1][pm[0]] = n;
      t[2] = t[1];
      t[2][pm[1]] = n;
      t[3] = {n, n, n};
      bisect(t, 0, std::nullopt);
    }
  }

  static long long length2(const GridPoint& a, const GridPoint& b) {
    long long s = 0;
    for (int i = 0; i < 3; ++i) s += static_cast<long long>(a[i] - b[i]) * (a[i] - b[i]);
    return s;
  }

  // Returns the split vertex of t, if t can be bisected on the grid.
  static std::optional<std::pair<int, int>> longestEdge(const std::array<GridPoint, 4>& t) {
    long long best = -1;
    int count = 0;
    std::pair<int, int> e{0, 0};
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const long long l = length2(t[i], t[j]);
        if (l > best) {
          best = l;
          count = 1;
          e = {i, j};
        } else if (l == best) {
          ++count;
        }
      }
    EXPECT_EQ(count, 1) << "the longest edge of a bisection tetrahedron is unique";
    for (int a = 0; a < 3; ++a)
      if ((t[e.first][a] + t[e.second][a]) % 2 != 0) return std::nullopt;
    return e;
  }

  void bisect(const std::array<GridPoint, 4>& t, int depth, std::optional<GridPoint> parent) {
    const auto e = longestEdge(t);
    if (!e) return;
    GridPoint m;
    for (int a = 0; a < 3; ++a) m[a] = (t[e->first][a] + t[e->second][a]) / 2;
    BruteDiamond& d = diamonds[m];
    d.splitEdges.insert(sorted(t[e->first], t[e->second]));
    d.depths.insert(depth);
    ++d.tets;
    for (int i = 0; i < 4; ++i)
      if (i != e->first && i != e->second) d.ring.insert(t[i]);
    if (parent) d.parents.insert(*parent);
    for (int keep : {e->first, e->second}) {
      std::array<GridPoint, 4> child = t;
      child[keep == e->first ? e->second : e->first] = m;
      if (const auto ce = longestEdge(child)) {
        GridPoint cm;
        for (int a = 0; a < 3; ++a) cm[a] = (child[ce->first][a] + child[ce->second][a]) / 2;
        diamonds[m].children.insert(cm);
      }
      bisect(child, depth + 1, m);
    }
  }
};

template <class Points>
std::set<GridPoint> asSet(const Points& v) {
  return {v.begin(), v.end()};
}

class LebGridAgainstBisection : public ::testing::TestWithParam<int> {};

TEST_P(LebGridAgainstBisection, EveryPointButTheCornersIsTheSplitVertexOfOneDiamond) {
  const LebGrid g = makeLebGrid(GetParam());
  const BruteForce brute(g.k);
  int points = 0;
  for (const GridPoint& p : test_support::gridPoints(g)) {
    const auto it = brute.diamonds.find(p);
    if (isRootCorner(g, p)) {
      EXPECT_EQ(it, brute.diamonds.end());
      EXPECT_EQ(classifyPoint(g, p).level, -1);
      continue;
    }
    ++points;
    ASSERT_NE(it, brute.diamonds.end()) << pointText(p) << " is never inserted";
    const BruteDiamond& d = it->second;
    ASSERT_EQ(d.splitEdges.size(), 1u) << "one split edge per split vertex (conforming bisection)";
    ASSERT_EQ(d.depths.size(), 1u);
    const SplitEdge e = splitEdge(g, p);
    EXPECT_EQ(sorted(e.a, e.b), *d.splitEdges.begin()) << pointText(p);
    const LebPointClass c = classifyPoint(g, p);
    EXPECT_EQ(c.level, *d.depths.begin()) << pointText(p);
    EXPECT_LT(classifyPoint(g, e.a).level, c.level);
    EXPECT_LT(classifyPoint(g, e.b).level, c.level);
    EXPECT_EQ(asSet(diamondRing(g, p)), d.ring) << pointText(p);
    EXPECT_EQ(asSet(diamondParents(g, p)), d.parents) << pointText(p);
    EXPECT_EQ(asSet(diamondChildren(g, p)), d.children) << pointText(p);
    // Full diamonds inside the grid: 6, 4 and 8 tetrahedra for phases 2, 1, 0.
    if (d.ring.size() == (c.phase == 2 ? 6u : c.phase == 1 ? 4u : 8u)) {
      EXPECT_EQ(d.tets, c.phase == 2 ? 6 : c.phase == 1 ? 4 : 8);
    }
  }
  EXPECT_EQ(points, static_cast<int>(g.pointCount()) - 8);
  EXPECT_EQ(brute.diamonds.size(), g.pointCount() - 8);
}

INSTANTIATE_TEST_SUITE_P(K, LebGridAgainstBisection, ::testing::Values(1, 2, 3, 4));

TEST(LebGrid, ParentsAreTheRingsPointsOneLevelCoarserInTheRingsOrder) {
  // The definition, point by point: diamondParents computes them without classifying the ring.
  for (int k = 1; k <= 5; ++k) {
    const LebGrid g = makeLebGrid(k);
    for (const GridPoint& p : test_support::gridPoints(g)) {
      if (isRootCorner(g, p)) {
        EXPECT_THROW(diamondParents(g, p), std::invalid_argument);
        continue;
      }
      const int level = classifyPoint(g, p).level;
      std::vector<GridPoint> expected;
      if (level > 0)
        for (const GridPoint& q : diamondRing(g, p))
          if (classifyPoint(g, q).level == level - 1) expected.push_back(q);
      const DiamondPoints parents = diamondParents(g, p);
      ASSERT_EQ(std::vector<GridPoint>(parents.begin(), parents.end()), expected)
          << "k " << k << " point " << pointText(p);
    }
  }
}

TEST(LebGrid, DiamondCountsInsideTheGrid) {
  const LebGrid g = makeLebGrid(4);
  // An interior point of each phase: parents 3 / 2 / 4, children 6 / 4 / 8.
  const GridPoint cube{4 + 2, 4 + 2, 4 + 2}, face{6, 6, 8}, edge{6, 8, 8};
  EXPECT_EQ(classifyPoint(g, cube).phase, 2);
  EXPECT_EQ(classifyPoint(g, face).phase, 1);
  EXPECT_EQ(classifyPoint(g, edge).phase, 0);
  EXPECT_EQ(diamondParents(g, cube).size(), 3u);
  EXPECT_EQ(diamondParents(g, face).size(), 2u);
  EXPECT_EQ(diamondParents(g, edge).size(), 4u);
  EXPECT_EQ(diamondChildren(g, cube).size(), 6u);
  EXPECT_EQ(diamondChildren(g, face).size(), 4u);
  EXPECT_EQ(diamondChildren(g, edge).size(), 8u);
  EXPECT_TRUE(diamondParents(g, {8, 8, 8}).empty());  // the root diamond
}

TEST(LebGrid, CoveringGridsAndLimits) {
  EXPECT_EQ(lebGridCovering({2, 2, 2}).k, 0);
  EXPECT_EQ(lebGridCovering({3, 1, 1}).k, 1);
  EXPECT_EQ(lebGridCovering({37, 5, 101}).k, 7);
  EXPECT_EQ(lebGridCovering({256, 256, 128}).k, 8);
  EXPECT_EQ(lebGridCovering({129, 129, 129}).k, 7);
  EXPECT_EQ(lebGridCovering({1026, 1, 1}).k, 11);
  EXPECT_EQ(lebGridCovering({2048, 2048, 1920}).k, 11);  // the paper's largest volume
  EXPECT_THROW(lebGridCovering({2050, 1, 1}), std::invalid_argument);
  EXPECT_THROW(lebGridCovering({0, 1, 1}), std::invalid_argument);
  EXPECT_THROW(makeLebGrid(12), std::invalid_argument);
  EXPECT_NO_THROW(requireIndexedGrid(makeLebGrid(10), "x"));
  EXPECT_THROW(requireIndexedGrid(makeLebGrid(11), "x"), std::invalid_argument);
  EXPECT_THROW(splitEdge(makeLebGrid(2), {0, 4, 0}), std::invalid_argument);
  EXPECT_THROW(classifyPoint(makeLebGrid(2), {0, 5, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
