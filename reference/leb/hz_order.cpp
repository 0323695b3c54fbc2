#include "reference/leb/hz_order.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace voxref::ref {

HzOrder::HzOrder(const LebGrid& grid) : grid_(makeLebGrid(grid.k)) {
  levelBegin_.push_back(0);
  levelBegin_.push_back(8);  // the corners
  for (int level = 0; level < grid_.levelCount(); ++level) {
    Level lv;
    lv.scaleLog2 = grid_.k - 1 - level / 3;
    lv.oddCount = 3 - level % 3;
    lv.cellBits = grid_.k - lv.scaleLog2 - 1;
    const std::uint64_t n = std::uint64_t{1} << lv.cellBits;
    std::uint64_t begin = levelBegin_.back();
    for (unsigned b = 0; b < 8; ++b) {
      Block& block = lv.blocks[b];
      block.begin = begin;
      block.freeMask = ~b & 7u;
      block.freeAxes = std::popcount(block.freeMask);
      for (unsigned o = 1; o < 8; ++o)
        if (std::popcount(o) == lv.oddCount && (o & b) == 0) block.orientations.push_back(o);
      std::uint64_t cells = 1;
      for (int a = 0; a < block.freeAxes; ++a) cells *= n;
      block.cells = block.orientations.empty() ? 0 : cells;
      begin += cells * block.orientations.size();
    }
    levels_.push_back(std::move(lv));
    levelBegin_.push_back(begin);
  }
  if (levelBegin_.back() != grid_.pointCount()) throw std::logic_error("hierarchical z-order does not cover the grid");
}

bool HzOrder::allInside(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end) const {
  end = std::min(end, size());
  const int side = grid_.side();
  for (std::uint64_t h = begin; h < std::min<std::uint64_t>(end, 8); ++h)
    for (int a = 0; a < 3; ++a)
      if (((h >> a) & 1u) && side >= dims[static_cast<std::size_t>(a)]) return false;
  return forEachBlockPart(dims, begin, end, [&](const BlockPart& part) {
    if (part.boundaryOutside) return false;
    const int nf = part.nf, scale = 1 << part.lv.scaleLog2, cellSide = 2 * scale;
    if (nf == 0) return true;  // the one point at (side, side, side): inside, as just checked
    // The block's cells of the range lie in the Morton node of their first and last codes'
    // common prefix: a cube of 2^r cells from c0 (mortonDescend's nodes).
    const int r = (std::bit_width(part.mlo ^ (part.mhi - 1)) + nf - 1) / nf;
    int c0[3] = {0, 0, 0};
    mortonDecode(part.mlo >> (nf * r) << (nf * r), nf, c0);
    for (int i = 0; i < nf; ++i)  // the node's last cell, at its odd offset: p = cellSide c + scale
      if (cellSide * (c0[i] + (1 << r) - 1) + scale >= dims[static_cast<std::size_t>(part.axis[i])]) return false;
    return true;
  });
}

std::uint64_t HzOrder::countInside(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end) const {
  end = std::min(end, size());
  if (begin >= end) return 0;
  if (allInside(dims, begin, end)) return end - begin;
  std::uint64_t n = 0;
  forEachInside(dims, begin, end, [&](std::uint64_t, const GridPoint&, int, int, unsigned) { ++n; });
  return n;
}

std::uint64_t HzOrder::index(const GridPoint& p) const { return index(p, classifyPoint(grid_, p)); }

std::uint64_t HzOrder::index(const GridPoint& p, const LebPointClass& c) const {
  if (c.level < 0) return (p[0] ? 1u : 0u) | (p[1] ? 2u : 0u) | (p[2] ? 4u : 0u);
  const Level& lv = levels_[static_cast<std::size_t>(c.level)];
  const int n = 1 << lv.cellBits;
  unsigned boundary = 0;
  int free[3], count = 0;
  for (int a = 0; a < 3; ++a) {
    const int cell = p[a] >> (lv.scaleLog2 + 1);  // the cell of side 2h; p[a] >= 0 inside the grid
    if (cell == n)
      boundary |= 1u << a;
    else
      free[count++] = cell;
  }
  const Block& block = lv.blocks[boundary];
  const auto it = std::find(block.orientations.begin(), block.orientations.end(), c.oddAxes);
  return block.begin + mortonEncode(free, count) * block.orientations.size() +
         static_cast<std::uint64_t>(it - block.orientations.begin());
}

void HzOrder::indicesBelow(std::uint64_t h, const GridPoint& p, const LebPointClass& c, std::uint64_t below[3]) const {
  const Level& lv = levels_[static_cast<std::size_t>(c.level)];
  const int shift = lv.scaleLog2 + 1, n = 1 << lv.cellBits;
  unsigned boundary = 0;
  for (int a = 0; a < 3; ++a)
    if ((p[static_cast<std::size_t>(a)] >> shift) == n) boundary |= 1u << a;
  const Block& block = lv.blocks[boundary];
  const std::uint64_t orientations = block.orientations.size(), at = h - block.begin;
  // A block's cells hold 1, 2 or 3 points: divisions by constants (multiplications).
  const std::uint64_t code = orientations == 1 ? at : orientations == 2 ? at / 2 : at / 3;
  const std::uint64_t orientation = at - code * orientations;
  // The bits of a free axis's coordinate in the code: every freeAxes-th bit from its place among
  // the block's free axes (mortonEncode's order).
  static constexpr std::uint64_t kEvery[4] = {0, ~std::uint64_t{0}, 0x5555555555555555ULL, 0x9249249249249249ULL};
  int position = 0;
  for (int a = 0; a < 3; ++a) {
    const bool free = ((boundary >> a) & 1u) == 0;
    if (p[static_cast<std::size_t>(a)] >> shift == 0) {  // p[a] < 2h
      below[a] = kNoIndex;
    } else if (!free) {  // q leaves the far boundary's block
      GridPoint q = p;
      q[static_cast<std::size_t>(a)] -= 1 << shift;
      below[a] = index(q, c);
    } else {
      const std::uint64_t mask = kEvery[block.freeAxes] << position;
      const std::uint64_t down = (((code & mask) - (std::uint64_t{1} << position)) & mask) | (code & ~mask);
      below[a] = block.begin + down * orientations + orientation;
    }
    if (free) ++position;
  }
}

GridPoint HzOrder::point(std::uint64_t h) const {
  if (h >= size())
    throw std::out_of_range("hierarchical index " + std::to_string(h) + " is outside the grid of " +
                            std::to_string(size()) + " points");
  HzCursor cursor(*this, h);
  return cursor.point();
}

HzCursor::HzCursor(const HzOrder& order, std::uint64_t start) : order_(&order), h_(start) {
  if (h_ >= order.size()) return;
  if (h_ < 8) {
    level_ = -1;
    cell_ = h_;
  } else {
    level_ = static_cast<int>(std::upper_bound(order.levelBegin_.begin(), order.levelBegin_.end(), h_) -
                              order.levelBegin_.begin()) -
             2;
    const HzOrder::Level& lv = order.levels_[static_cast<std::size_t>(level_)];
    block_ = 7;
    while (lv.blocks[block_].begin > h_) --block_;
    const HzOrder::Block& b = lv.blocks[block_];
    const std::uint64_t r = h_ - b.begin;
    cell_ = r / b.orientations.size();
    orientation_ = static_cast<std::size_t>(r % b.orientations.size());
    computeCell();
  }
  computePoint();
}

}  // namespace voxref::ref
