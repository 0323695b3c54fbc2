#include "reference/iso/diamond_bounds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/common/parallel.h"
#include "reference/iso/diamond_range.h"
#include "reference/leb/hz_order.h"

namespace voxref::ref {

DiamondBounds computeDiamondBounds(const LebGrid& grid, const std::vector<std::uint16_t>& values, int threads) {
  requireIndexedGrid(grid, "diamond bounds");
  DiamondBounds b;
  b.grid = grid;
  const std::uint64_t n = grid.pointCount();
  b.assign(n);
  const HzOrder order(grid);
  forLevelsFinestFirst(order, grid.levelCount() - 1, threads, [&](const HzCursor& c, int level) {
    const GridPoint& p = c.point();
    const DiamondRange r = foldDiamond(
        grid, p, c.scaleLog2(), c.oddAxes(), level + 1 < grid.levelCount(),
        [&](const GridPoint& q) { return static_cast<int>(values[grid.linearIndex(q)]); },
        [&](const GridPoint& q) { return b.at(grid.linearIndex(q)); });
    b.store(grid.linearIndex(p), r);
  });
  return b;
}

namespace {
constexpr char kBoundsMagic[4] = {'V', 'X', 'L', 'D'};
constexpr std::uint16_t kBoundsVersion = 1;
constexpr std::size_t kBoundsHeader = 8;
}  // namespace

std::string serializeDiamondBounds(const DiamondBounds& b) {
  ByteWriter w;
  w.bytes(kBoundsMagic, 4);
  w.le<std::uint16_t>(kBoundsVersion);
  w.le<std::uint8_t>(static_cast<std::uint8_t>(b.grid.k));
  w.le<std::uint8_t>(0);
  for (std::uint64_t i = 0; i < b.grid.pointCount(); ++i) {
    w.le<std::uint16_t>(b.min[i]);
    w.le<std::uint16_t>(b.max[i]);
    w.le<std::uint32_t>(static_cast<std::uint32_t>(2.0f * b.error[i]));  // halves are exact
  }
  w.le<std::uint32_t>(crc32(w.str()));
  return std::move(w.str());
}

DiamondBounds parseDiamondBounds(std::string_view bytes) {
  ByteReader r(bytes);
  if (r.take(4, "magic") != std::string_view(kBoundsMagic, 4))
    ByteReader::fail(0, "magic: expected 'VXLD' (not diamond bounds)");
  r.le<std::uint16_t>("version", kBoundsVersion, kBoundsVersion);
  DiamondBounds b;
  b.grid = makeLebGrid(r.le<std::uint8_t>("k", 0, kMaxIndexedLebK));
  r.le<std::uint8_t>("reserved", 0, 0);
  const std::uint64_t n = b.grid.pointCount();
  const std::uint64_t expected = kBoundsHeader + 8 * n + 4;
  if (bytes.size() != expected)
    ByteReader::fail(bytes.size() < expected ? bytes.size() : expected,
                     "size: a grid of " + std::to_string(n) + " points needs " + std::to_string(expected) +
                         " bytes, the stream has " + std::to_string(bytes.size()));
  if (!crc32Matches(bytes.substr(0, expected - 4), static_cast<std::uint32_t>(loadLe(bytes.data() + expected - 4, 4))))
    ByteReader::fail(expected - 4, "crc32: the bounds are corrupt");
  b.min.resize(n);
  b.max.resize(n);
  b.error.resize(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::size_t at = r.offset();
    b.min[i] = r.le<std::uint16_t>("min");
    b.max[i] = r.le<std::uint16_t>("max");
    b.error[i] = static_cast<float>(r.le<std::uint32_t>("error")) / 2.0f;
    if (b.min[i] > b.max[i]) ByteReader::fail(at, "point " + std::to_string(i) + ": min above max");
  }
  return b;
}

GridBox diamondBox(const LebGrid& grid, const GridPoint& p) {
  // Every phase's vertices reach p +- h on every axis (phase 2: the cube of side 2h around p;
  // phase 1: the face square on its odd axes, the two cube centres on its even one; phase 0: the
  // split edge, the face centres and the cube centres around it), and the ring is symmetric about
  // p, so dropping the vertices outside the grid clips that box to the grid (leb_grid.h).
  const LebPointClass c = classifyPoint(grid, p);
  if (c.level < 0)
    throw std::invalid_argument("the root corner " + pointText(p) + " is not the split vertex of a diamond");
  const int h = 1 << c.scaleLog2, side = grid.side();
  GridBox box{p, p};
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = std::max(0, p[a] - h);
    box.hi[a] = std::min(side, p[a] + h);
  }
  return box;
}

}  // namespace voxref::ref
