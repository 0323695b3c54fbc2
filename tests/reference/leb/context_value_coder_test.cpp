// The context coder's pieces (reference/leb/context_value_coder.h; reference/leb/FORMAT.md,
// "Context pages"): the geometry its decoder relies on, checked on every point of small grids, its
// prediction against a brute-force one, and its page reader's refusals of corrupt bytes.
#include "reference/leb/context_value_coder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_grid.h"

namespace voxref::ref {
namespace {

// Every point of the grid with its class, in index order.
template <class F>
void forEachGridPoint(const HzOrder& order, F&& f) {
  for (HzCursor c(order, 0); !c.done(); c.next())
    f(c.index(), c.point(),
      LebPointClass{c.level(), c.scaleLog2(), std::max(0, std::popcount(c.oddAxes()) - 1), c.oddAxes()});
}

// reference/leb/FORMAT.md: a neighbour p - 2h on an axis is of p's class and precedes p; every
// corner precedes the first level of p's scale (the whole-volume decoder's waves rest on it).
TEST(ContextValueCoder, NeighboursShareTheClassAndCornersAreCoarser) {
  for (int k = 1; k <= 6; ++k) {
    const LebGrid grid{k};
    const HzOrder order(grid);
    std::uint64_t neighbours = 0, corners = 0;
    forEachGridPoint(order, [&](std::uint64_t h, const GridPoint& p, const LebPointClass& c) {
      if (c.level < 0) return;
      const int hh = 1 << c.scaleLog2;
      for (int a = 0; a < 3; ++a) {
        if (p[a] < 2 * hh) continue;
        GridPoint q = p;
        q[a] -= 2 * hh;
        const LebPointClass qc = classifyPoint(grid, q);
        ASSERT_EQ(qc.level, c.level) << "k " << k << " point " << p[0] << "," << p[1] << "," << p[2];
        ASSERT_EQ(qc.oddAxes, c.oddAxes);
        ASSERT_LT(order.index(q), h);
        ASSERT_EQ(order.index(q, c), order.index(q));
        ++neighbours;
      }
      const std::uint64_t scaleBegin = order.levelBegin(c.level - c.level % 3);
      for (int signs = 0; signs < 8; ++signs) {  // a sign on each odd axis: bit a set for +h
        if (signs & ~static_cast<int>(c.oddAxes)) continue;
        GridPoint q = p;
        for (int a = 0; a < 3; ++a)
          if ((c.oddAxes >> a) & 1u) q[a] += ((signs >> a) & 1) ? hh : -hh;
        ASSERT_LT(order.index(q), scaleBegin);
        ++corners;
      }
    });
    EXPECT_GT(neighbours, 0u);
    EXPECT_GT(corners, 0u);
  }
}

// The prediction of a point from its corners, against every point of the volume that differs from
// p by exactly h on each odd axis and not at all on the others (a search of the whole volume).
TEST(ContextValueCoder, TheCornersPredictionIsTheRoundedMeanOfTheCornersInside) {
  const Dims3 dims{11, 6, 9};
  std::mt19937 rng(7);
  std::vector<std::int32_t> v(static_cast<std::size_t>(dims[0] * dims[1] * dims[2]));
  for (auto& s : v) s = static_cast<std::int32_t>(rng() % 256);
  const auto at = [&](const GridPoint& q) {
    return v[static_cast<std::size_t>((q[2] * dims[1] + q[1]) * dims[0] + q[0])];
  };
  const LebGrid grid = lebGridCovering(dims);
  const HzOrder order(grid);
  int checked = 0;
  order.forEachInside(dims, 8, order.size(), [&](std::uint64_t, const GridPoint& p, int, int s, unsigned odd) {
    const int h = 1 << s;
    std::int64_t sum = 0;
    std::int32_t lo = 1 << 20, hi = -1;
    int m = 0;
    for (int z = 0; z < dims[2]; ++z)
      for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
          const GridPoint q{x, y, z};
          bool corner = true;
          for (int a = 0; a < 3; ++a)
            corner = corner && (((odd >> a) & 1u) ? std::abs(q[a] - p[a]) == h : q[a] == p[a]);
          if (!corner) continue;
          sum += at(q);
          lo = std::min(lo, at(q));
          hi = std::max(hi, at(q));
          ++m;
        }
    ASSERT_GE(m, 1);
    const CornerPrediction cp = cornerPrediction(p, s, odd, dims, at);
    // floor((sum + floor(m/2)) / m) by exact integer division of non-negative values.
    EXPECT_EQ(cp.prediction, static_cast<std::int32_t>((sum + m / 2) / m));
    EXPECT_EQ(cp.rangeBucket, contextRangeBucket(hi - lo));
    ++checked;
  });
  EXPECT_EQ(checked, dims[0] * dims[1] * dims[2] - 1);  // all but the root corner (0, 0, 0)
}

// reference/leb/FORMAT.md's table of the range's buckets.
TEST(ContextValueCoder, TheRangeBucketsAreTheFormatsTable) {
  const std::pair<int, int> table[] = {{0, 0}, {1, 1},  {2, 2},  {3, 3},  {4, 3},  {5, 4},   {8, 4},
                                       {9, 5}, {16, 5}, {17, 6}, {32, 6}, {33, 7}, {255, 7}, {65535, 7}};
  for (const auto& [range, bucket] : table) EXPECT_EQ(contextRangeBucket(range), bucket) << range;
}

// A page's bytes against its reader: the page of a small volume, damaged.
class ContextPage : public ::testing::Test {
 protected:
  void SetUp() override {
    std::mt19937 rng(3);
    for (auto& s : v) s = static_cast<std::int32_t>(rng() % 256);
    page = encodeContextPage(order, dims, 8, 12, 0,
                             [this](const GridPoint& q) { return v[static_cast<std::size_t>(linear(q))]; });
  }
  int linear(const GridPoint& q) const { return (q[2] * dims[1] + q[1]) * dims[0] + q[0]; }
  // The values decoded from `bytes`, or the reader's error.
  std::string errorOf(const std::string& bytes) const {
    std::vector<std::int32_t> out(v.size(), -1);
    try {
      ContextPageReader reader(bytes, 8, 12, 0, 1000, "data page 0");
      reader.decode(
          order, dims, [&](const GridPoint& q) { return out[static_cast<std::size_t>(linear(q))]; },
          [&](std::uint64_t, const GridPoint& p, std::int32_t value) {
            out[static_cast<std::size_t>(linear(p))] = value;
          });
    } catch (const StreamError& e) {
      return e.what();
    }
    return out == v ? "" : "decoded other values";
  }
  Dims3 dims{5, 4, 3};
  HzOrder order{lebGridCovering(dims)};
  std::vector<std::int32_t> v = std::vector<std::int32_t>(60);
  std::string page;
};

TEST_F(ContextPage, TheIntactPageDecodesToItsValues) { EXPECT_EQ(errorOf(page), ""); }

TEST_F(ContextPage, DamagedPagesAreRefusedWithTheirOffset) {
  EXPECT_EQ(errorOf(page.substr(0, 4)), "offset 1000: data page 0: a page of the context coder has at least 5 bytes");
  std::string first = page;
  first[0] = 1;
  EXPECT_EQ(errorOf(first), "offset 1000: data page 0: the first byte of a context page must be 0");
  EXPECT_EQ(errorOf(page + std::string(3, '\0')),
            "offset " + std::to_string(1000 + page.size()) + ": data page 0: 3 bytes left after the last value");
  // Cut short: the decoder runs past the page's end inside a value.
  EXPECT_NE(errorOf(page.substr(0, page.size() - 6)).find(": data page 0: the page ends inside value "),
            std::string::npos);
}

}  // namespace
}  // namespace voxref::ref
