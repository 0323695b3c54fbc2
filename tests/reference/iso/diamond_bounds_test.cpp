// Diamond bounds against a brute-force range over each diamond's tetrahedra, and the error in
// closed form on fields whose deltas are known.
#include "reference/iso/diamond_bounds.h"

#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "reference/common/byte_stream.h"
#include "reference/leb/diamond_mesh.h"
#include "tests/reference/iso/iso_test_fields.h"
#include "tests/reference/leb/grid_points.h"

namespace voxref::ref {
namespace {

using test_support::volumeOf;

// Whether grid point q lies in the closed tetrahedron t (exact integer orientation tests).
bool insideTetrahedron(const Tetrahedron& t, const GridPoint& q) {
  auto orient = [](const GridPoint& a, const GridPoint& b, const GridPoint& c, const GridPoint& d) {
    long long m[3][3];
    for (int r = 0; r < 3; ++r) {
      const GridPoint& p = r == 0 ? b : r == 1 ? c : d;
      for (int k = 0; k < 3; ++k) m[r][k] = p[k] - a[k];
    }
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const long long whole = orient(t.v[0], t.v[1], t.v[2], t.v[3]);
  for (int i = 0; i < 4; ++i) {
    Tetrahedron s = t;
    s.v[static_cast<std::size_t>(i)] = q;
    const long long part = orient(s.v[0], s.v[1], s.v[2], s.v[3]);
    if ((whole > 0 && part < 0) || (whole < 0 && part > 0)) return false;
  }
  return true;
}

TEST(DiamondBounds, ContainTheRangeOverEveryDiamondsTetrahedra) {
  std::mt19937 rng(85);
  std::uniform_int_distribution<int> value(0, 255);
  const Volume<std::uint16_t> v = volumeOf({9, 9, 9}, [&](int, int, int) { return value(rng); });
  const DenseGridField field = test_support::denseField(v);
  const LebGrid g = field.grid();
  const DiamondBounds b = computeDiamondBounds(g, field.values(), 2);
  int diamonds = 0;
  for (const GridPoint& d : test_support::diamondPoints(g)) {
    // The diamond's tetrahedra: split its parents, take the leaves whose split vertex is d.
    DiamondMesh mesh(g);
    for (const GridPoint& p : diamondParents(g, d)) mesh.split(p);
    std::vector<Tetrahedron> tets;
    mesh.forEachLeaf([&](const Tetrahedron& t, const GridPoint& owner) {
      if (owner == d) tets.push_back(t);
    });
    ASSERT_FALSE(tets.empty());
    int lo = 1 << 30, hi = -1;
    for (const GridPoint& q : test_support::gridPoints(g))
      for (const Tetrahedron& t : tets)
        if (insideTetrahedron(t, q)) {
          const int s = v.at(q[0], q[1], q[2]);
          lo = std::min(lo, s);
          hi = std::max(hi, s);
          break;
        }
    const std::uint64_t i = g.linearIndex(d);
    EXPECT_LE(b.min[i], lo) << pointText(d);
    EXPECT_GE(b.max[i], hi) << pointText(d);
    ++diamonds;
  }
  EXPECT_EQ(diamonds, 9 * 9 * 9 - 8);
}

TEST(DiamondBounds, ErrorIsZeroOnALinearFieldAndNestedOnASpike) {
  // f = 2x + 4y + 8z: every midpoint prediction is exact.
  const Volume<std::uint16_t> linear =
      volumeOf({17, 17, 17}, [](int x, int y, int z) { return 2.0 * x + 4.0 * y + 8.0 * z; });
  const DenseGridField lf = test_support::denseField(linear);
  const DiamondBounds lb = computeDiamondBounds(lf.grid(), lf.values());
  EXPECT_EQ(*std::max_element(lb.error.begin(), lb.error.end()), 0.0f);
  // One spike of 200 at a point with three odd coordinates: its delta is 200, its
  // ancestors inherit it, the finer neighbours predicted from it differ by 100.
  Volume<std::uint16_t> spike({17, 17, 17}, 0);
  spike.at(5, 9, 3) = 200;
  const DenseGridField sf = test_support::denseField(spike);
  const LebGrid g = sf.grid();
  const DiamondBounds sb = computeDiamondBounds(g, sf.values());
  EXPECT_EQ(sb.errorOf({5, 9, 3}), 200.0f);
  EXPECT_EQ(sb.errorOf({8, 8, 8}), 200.0f);  // the root diamond
  for (const GridPoint& d : test_support::diamondPoints(g)) {
    for (const GridPoint& c : diamondChildren(g, d)) ASSERT_GE(sb.errorOf(d), sb.errorOf(c));
  }
}

TEST(DiamondBounds, SameForEveryThreadCount) {
  const Volume<std::uint16_t> v = test_support::ballVolume({20, 11, 17}, 9.0, 5.0, 7.0);
  const DenseGridField f = test_support::denseField(v);
  const DiamondBounds a = computeDiamondBounds(f.grid(), f.values(), 1),
                      b = computeDiamondBounds(f.grid(), f.values(), 2);
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
  EXPECT_EQ(a.error, b.error);
}

}  // namespace
}  // namespace voxref::ref

namespace voxref::ref {
namespace {

TEST(DiamondBox, IsTheBoxOfTheSplitVertexItsEdgeAndItsRing) {
  // The closed form (p +- h clipped to the grid) against the box of the vertices themselves.
  for (int k = 1; k <= 4; ++k) {
    const LebGrid g = makeLebGrid(k);
    for (const GridPoint& p : test_support::diamondPoints(g)) {
      const SplitEdge e = splitEdge(g, p);
      GridBox want{p, p};
      const DiamondPoints ring = diamondRing(g, p);
      std::vector<GridPoint> vertices(ring.begin(), ring.end());
      vertices.push_back(e.a);
      vertices.push_back(e.b);
      for (const GridPoint& q : vertices)
        for (int a = 0; a < 3; ++a) {
          want.lo[a] = std::min(want.lo[a], q[a]);
          want.hi[a] = std::max(want.hi[a], q[a]);
        }
      const GridBox got = diamondBox(g, p);
      ASSERT_EQ(got.lo, want.lo) << "k " << k << " point " << pointText(p);
      ASSERT_EQ(got.hi, want.hi) << "k " << k << " point " << pointText(p);
    }
  }
  EXPECT_THROW(diamondBox(makeLebGrid(2), GridPoint{0, 0, 4}), std::invalid_argument);
}

TEST(DiamondBoundsFile, RoundTripsAndRefusesCorruption) {
  const Volume<std::uint16_t> v = test_support::ballVolume({20, 11, 17}, 9.0, 5.0, 7.0);
  const DenseGridField f = test_support::denseField(v);
  const DiamondBounds b = computeDiamondBounds(f.grid(), f.values());
  const std::string bytes = serializeDiamondBounds(b);
  EXPECT_EQ(bytes.size(), 12 + 8 * f.grid().pointCount());
  const DiamondBounds back = parseDiamondBounds(bytes);
  EXPECT_EQ(back.grid.k, b.grid.k);
  EXPECT_EQ(back.min, b.min);
  EXPECT_EQ(back.max, b.max);
  EXPECT_EQ(back.error, b.error);
  auto error = [](const std::string& s) {
    try {
      parseDiamondBounds(s);
    } catch (const StreamError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("JUNK" + bytes.substr(4)).find("not diamond bounds"), std::string::npos);
  EXPECT_NE(error(bytes.substr(0, bytes.size() - 1)).find("size:"), std::string::npos);
  std::string flipped = bytes;
  flipped[100] = static_cast<char>(flipped[100] ^ 1);
  EXPECT_NE(error(flipped).find("crc32"), std::string::npos);
}

// The contract of diamond_bounds.h ("Memory: ..."): a header of k = 10 claims 8 bytes for each of
// 1025^3 points, 8.6 GB; a file of 108 bytes is refused by its size before anything is allocated.
TEST(DiamondBoundsFile, AHugeGridClaimIsRefusedBeforeAllocating) {
  std::string bytes = "VXLD";
  bytes += '\x01';
  bytes += '\x00';
  bytes += '\x0a';  // k = 10
  bytes += '\x00';
  bytes += std::string(100, '\0');
  try {
    parseDiamondBounds(bytes);
    FAIL() << "no error";
  } catch (const StreamError& e) {
    EXPECT_EQ(std::string(e.what()),
              "offset 108: size: a grid of 1076890625 points needs 8615125012 bytes, the stream has 108");
  }
}

}  // namespace
}  // namespace voxref::ref
