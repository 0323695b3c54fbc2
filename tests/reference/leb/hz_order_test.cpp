#include "reference/leb/hz_order.h"

#include <algorithm>
#include <map>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

class HzOrderOnGrid : public ::testing::TestWithParam<int> {};

TEST_P(HzOrderOnGrid, IsABijectionWithLevelsFirstAndCoarserPredictors) {
  const LebGrid g = makeLebGrid(GetParam());
  const HzOrder order(g);
  ASSERT_EQ(order.size(), g.pointCount());
  std::vector<char> seen(g.pointCount(), 0);
  HzCursor cursor(order, 0);
  int previousLevel = -1;
  for (std::uint64_t h = 0; h < order.size(); ++h, cursor.next()) {
    ASSERT_FALSE(cursor.done());
    ASSERT_EQ(cursor.index(), h);
    const GridPoint p = order.point(h);
    ASSERT_EQ(cursor.point(), p) << h;
    ASSERT_TRUE(g.contains(p));
    ASSERT_EQ(order.index(p), h);
    ASSERT_EQ(seen[g.linearIndex(p)]++, 0) << "point visited twice";
    const LebPointClass pc = classifyPoint(g, p);
    ASSERT_EQ(order.index(p, pc), h);
    const int level = pc.level;
    ASSERT_EQ(cursor.level(), level);
    if (level >= 0) {
      ASSERT_EQ(cursor.scaleLog2(), pc.scaleLog2);
      ASSERT_EQ(cursor.oddAxes(), pc.oddAxes);
    }
    ASSERT_GE(level, previousLevel) << "levels first";
    ASSERT_GE(h, order.levelBegin(level));
    ASSERT_LT(h, order.levelBegin(level + 1));
    previousLevel = level;
    if (level >= 0) {
      const SplitEdge e = splitEdge(g, p);
      ASSERT_LT(order.index(e.a), h);
      ASSERT_LT(order.index(e.b), h);
      // The index of p - 2h on each axis, from p's (the context coder's neighbours), against the
      // closed form of the point itself.
      std::uint64_t below[3];
      order.indicesBelow(h, p, pc, below);
      for (int a = 0; a < 3; ++a) {
        const int step = 2 << pc.scaleLog2;
        GridPoint q = p;
        q[static_cast<std::size_t>(a)] -= step;
        ASSERT_EQ(below[a], p[static_cast<std::size_t>(a)] < step ? HzOrder::kNoIndex : order.index(q))
            << "axis " << a << " from index " << h;
      }
    }
  }
  EXPECT_TRUE(cursor.done());
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(g.pointCount()));
  EXPECT_THROW(order.point(order.size()), std::out_of_range);
}

INSTANTIATE_TEST_SUITE_P(K, HzOrderOnGrid, ::testing::Values(0, 1, 2, 3, 4, 5, 6));

TEST(HzOrder, InteriorOfALevelIsZOrderOverCells) {
  // Level 3 of k = 3 (scale 2, phase 2): cube centres at odd multiples of 2, cells of side 4,
  // n = 2: the eight interior cells in Morton order (x lowest bit).
  const HzOrder order(makeLebGrid(3));
  const std::uint64_t b = order.levelBegin(3);
  EXPECT_EQ(order.point(b + 0), (GridPoint{2, 2, 2}));
  EXPECT_EQ(order.point(b + 1), (GridPoint{6, 2, 2}));
  EXPECT_EQ(order.point(b + 2), (GridPoint{2, 6, 2}));
  EXPECT_EQ(order.point(b + 3), (GridPoint{6, 6, 2}));
  EXPECT_EQ(order.point(b + 4), (GridPoint{2, 2, 6}));
  EXPECT_EQ(order.point(b + 7), (GridPoint{6, 6, 6}));
  EXPECT_EQ(order.levelBegin(4) - order.levelBegin(3), 8u);
  // The corners come first, bit a of H for coordinate a.
  EXPECT_EQ(order.point(5), (GridPoint{8, 0, 8}));
}

TEST(HzOrder, LargeGridRoundTripsAtRandomIndices) {
  const HzOrder order(makeLebGrid(10));
  std::mt19937_64 rng(7);
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t h = rng() % order.size();
    const GridPoint p = order.point(h);
    ASSERT_EQ(order.index(p), h);
    ASSERT_EQ(order.index(p, classifyPoint(order.grid(), p)), h);
  }
  HzCursor c(order, order.size() - 3);
  c.next();
  c.next();
  EXPECT_FALSE(c.done());
  EXPECT_EQ(c.point(), order.point(order.size() - 1));
  c.next();
  EXPECT_TRUE(c.done());
}

TEST(Morton, RoundTripsAndInterleavesFromTheLowestBit) {
  const int a[3] = {1, 0, 0}, b[3] = {0, 1, 0}, c[3] = {0, 0, 1}, d[3] = {511, 300, 7};
  EXPECT_EQ(mortonEncode(a, 3), 1u);
  EXPECT_EQ(mortonEncode(b, 3), 2u);
  EXPECT_EQ(mortonEncode(c, 3), 4u);
  int back[3];
  mortonDecode(mortonEncode(d, 3), 3, back);
  EXPECT_EQ(back[0], 511);
  EXPECT_EQ(back[1], 300);
  EXPECT_EQ(back[2], 7);
  mortonDecode(mortonEncode(d, 2), 2, back);
  EXPECT_EQ(back[0], 511);
  EXPECT_EQ(back[1], 300);
}

}  // namespace
}  // namespace voxref::ref

namespace voxref::ref {
namespace {

// forEachInside visits exactly the points of the full walk (HzCursor) that lie inside the box and
// the range, in the same order, with the same classes.
TEST(HzOrder, ForEachInsideIsTheWalkFilteredByTheBox) {
  std::mt19937 rng(12);
  for (int k : {0, 1, 3, 5}) {
    const LebGrid g = makeLebGrid(k);
    const HzOrder order(g);
    for (int trial = 0; trial < 12; ++trial) {
      std::array<int, 3> dims;
      for (int a = 0; a < 3; ++a) dims[a] = 1 + static_cast<int>(rng() % static_cast<unsigned>(g.pointsPerAxis()));
      const std::uint64_t begin = rng() % order.size(), end = begin + rng() % (order.size() - begin + 1);
      std::vector<std::uint64_t> walked, visited;
      for (HzCursor c(order, begin); c.index() < end; c.next())
        if (c.point()[0] < dims[0] && c.point()[1] < dims[1] && c.point()[2] < dims[2]) walked.push_back(c.index());
      order.forEachInside(dims, begin, end, [&](std::uint64_t h, const GridPoint& p, int level, int s, unsigned odd) {
        visited.push_back(h);
        ASSERT_EQ(order.point(h), p);
        const LebPointClass pc = classifyPoint(g, p);
        ASSERT_EQ(level, pc.level);
        if (level >= 0) {
          ASSERT_EQ(s, pc.scaleLog2);
          ASSERT_EQ(odd, pc.oddAxes);
        }
      });
      EXPECT_EQ(visited, walked) << "k " << k << ", box " << dims[0] << "x" << dims[1] << "x" << dims[2] << ", ["
                                 << begin << ", " << end << ")";
    }
  }
}

// forEachCellInside gives, by groups of cells, the points of a range wholly inside the box that the
// cursor (the inverse of the index, point by point) walks: the same indices, points and odd axes,
// in the same order. Ranges of pages within one level and across levels, on grids and boxes where
// allInside holds.
TEST(HzOrder, ForEachCellInsideGivesTheCursorsPointsByGroupsOfCells) {
  std::mt19937 rng(44);
  for (int k : {1, 3, 5}) {
    const LebGrid g = makeLebGrid(k);
    const HzOrder order(g);
    const int n = g.pointsPerAxis();
    int ranges = 0;
    for (int trial = 0; trial < 400 && ranges < 60; ++trial) {
      std::array<int, 3> dims{n, n, n};
      if (trial % 2 == 1)
        for (int a = 0; a < 3; ++a) dims[a] = 1 + static_cast<int>(rng() % static_cast<unsigned>(n));
      const int p = static_cast<int>(rng() % 9);
      std::uint64_t begin = 8 + rng() % (order.size() - 8), end = begin + 1 + rng() % (std::uint64_t{1} << p);
      end = std::min(end, order.size());
      if (!order.allInside(dims, begin, end)) continue;
      ++ranges;
      std::vector<std::array<std::uint64_t, 5>> walked, given;
      for (HzCursor c(order, begin); !c.done() && c.index() < end; c.next())
        walked.push_back({c.index(), static_cast<std::uint64_t>(c.point()[0]), static_cast<std::uint64_t>(c.point()[1]),
                          static_cast<std::uint64_t>(c.point()[2]), c.oddAxes()});
      // The walk's tables are made once a block key: the groups of one key share their level, their
      // points' odd axes, their free axes and their coordinates on the others.
      std::map<int, std::vector<int>> byKey;
      order.forEachCellInside(dims, begin, end, [&](const HzOrder::CellGroup& grp) {
        std::vector<int> shape{grp.level, grp.scaleLog2, grp.orientations, grp.freeAxes, grp.fullPoints};
        for (int o = 0; o < grp.orientations; ++o) shape.push_back(static_cast<int>(grp.odd[o]));
        unsigned free = 0;
        for (int i = 0; i < grp.freeAxes; ++i) {
          shape.push_back(grp.axis[i]);
          free |= 1u << grp.axis[i];
        }
        for (int a = 0; a < 3; ++a)
          if (!((free >> a) & 1u)) shape.push_back(grp.base[a]);
        const auto [it, isNew] = byKey.emplace(grp.blockKey, shape);
        ASSERT_EQ(it->second, shape) << "block key " << grp.blockKey;
        ASSERT_LT(grp.first, grp.last);
        ASSERT_LE(grp.last, grp.fullPoints);
        ASSERT_LE(grp.fullPoints, HzOrder::CellGroup::kMaxPoints);
        std::uint64_t h = grp.h;
        for (int q = grp.first; q < grp.last; ++q, ++h) {
          const int cell = q / grp.orientations;
          const unsigned odd = grp.odd[q % grp.orientations];
          GridPoint pt = grp.base;
          for (int i = 0; i < grp.freeAxes; ++i) pt[grp.axis[i]] += ((cell >> i) & 1) << (grp.scaleLog2 + 1);
          for (int a = 0; a < 3; ++a) pt[a] += ((odd >> a) & 1u) ? (1 << grp.scaleLog2) : 0;
          ASSERT_EQ(classifyPoint(g, pt).level, grp.level);
          given.push_back({h, static_cast<std::uint64_t>(pt[0]), static_cast<std::uint64_t>(pt[1]),
                           static_cast<std::uint64_t>(pt[2]), odd});
        }
      });
      EXPECT_EQ(given, walked) << "k " << k << ", box " << dims[0] << "x" << dims[1] << "x" << dims[2] << ", [" << begin
                               << ", " << end << ")";
    }
    EXPECT_GE(ranges, 30) << "k " << k << ": too few ranges wholly inside the box were tried";
  }
}

// allInside is true only for ranges whose every point lies inside the box (the full walk checks
// each), always for a box that holds the grid, and for most pages of a box that cuts it; countInside
// counts the points the walk finds inside.
TEST(HzOrder, AllInsideHoldsOnlyForRangesWhollyInsideTheBox) {
  std::mt19937 rng(31);
  for (int k : {0, 1, 3, 5}) {
    const LebGrid g = makeLebGrid(k);
    const HzOrder order(g);
    const int n = g.pointsPerAxis();
    std::uint64_t trues = 0, wholly = 0;
    for (int trial = 0; trial < 200; ++trial) {
      std::array<int, 3> dims;
      for (int a = 0; a < 3; ++a) dims[a] = 1 + static_cast<int>(rng() % static_cast<unsigned>(n));
      if (trial % 4 == 0) dims = {n, n, n};
      // Ranges of pages (aligned, 2^p indices) and arbitrary ones.
      std::uint64_t begin = rng() % order.size(), end = begin + rng() % (order.size() - begin + 1);
      if (trial % 2 == 1) {
        const int p = static_cast<int>(rng() % 7);
        begin = (begin >> p) << p;
        end = begin + (std::uint64_t{1} << p);
      }
      bool all = true;
      std::uint64_t counted = 0;
      for (HzCursor c(order, begin); !c.done() && c.index() < end; c.next()) {
        const bool in = c.point()[0] < dims[0] && c.point()[1] < dims[1] && c.point()[2] < dims[2];
        all = all && in;
        counted += in ? 1 : 0;
      }
      const bool claimed = order.allInside(dims, begin, end);
      // countInside, by allInside where it holds and by the walk elsewhere, counts what the cursor
      // finds inside the box.
      EXPECT_EQ(order.countInside(dims, begin, end), counted) << "k " << k << ", box " << dims[0] << "x" << dims[1]
                                                              << "x" << dims[2] << ", [" << begin << ", " << end << ")";
      EXPECT_FALSE(claimed && !all) << "k " << k << ", box " << dims[0] << "x" << dims[1] << "x" << dims[2] << ", ["
                                    << begin << ", " << end << ")";
      if (dims == std::array<int, 3>{n, n, n}) {
        EXPECT_TRUE(claimed) << "k " << k << ": the box holds the grid";
      }
      trues += claimed ? 1 : 0;
      wholly += all ? 1 : 0;
    }
    EXPECT_GT(trues, wholly / 2) << "k " << k << ": allInside should find most ranges that lie wholly inside";
  }
  // The engine's box in its grid of k = 8: most stored pages of 2^12 lie wholly inside.
  const HzOrder order(makeLebGrid(8));
  const std::array<int, 3> engine{256, 256, 128};
  std::uint64_t pages = 0, inside = 0, claimed = 0;
  for (std::uint64_t page = 0; page < (order.size() >> 12); page += 7) {
    std::uint64_t count = 0;
    order.forEachInside(engine, page << 12, (page + 1) << 12,
                        [&](std::uint64_t, const GridPoint&, int, int, unsigned) { ++count; });
    pages += 1;
    inside += count == 4096 ? 1 : 0;
    claimed += order.allInside(engine, page << 12, (page + 1) << 12) ? 1 : 0;
    if (order.allInside(engine, page << 12, (page + 1) << 12)) {
      EXPECT_EQ(count, 4096u) << "page " << page;
    }
  }
  EXPECT_GT(claimed, inside * 9 / 10) << pages << " pages";
}

}  // namespace
}  // namespace voxref::ref
