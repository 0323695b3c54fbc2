// Hierarchical z-order on a (2^k + 1)^3 LEB grid: every grid point gets one index H in
// [0, (2^k + 1)^3), coarse levels first, z-order inside a level (Gregorski et al. 2004, section 2,
// after Pascucci and Frank's hierarchical z-order).
//
// The paper maps index 2^k to 0 ("the z-order curve tiles the dataset"), which sends the points of
// the far boundary onto those of the near one: on a (2^k + 1)^3 grid that is not a bijection.
// voxref's order is one, closed form in both directions:
//   H 0..7           the root corners, bit a of H set when the corner's coordinate a is 2^k;
//   then level 0, 1, ..., 3k - 1 (leb_grid.h), each level split into eight blocks:
//     A level of scale h and phase with m odd axes has its points in cells of side 2h: cell
//     c = floor(p / 2h) in [0, n]^3, n = 2^k / 2h, offset (p - 2h c) / h in {0, 1}^3 with m ones.
//     Block B (a subset of the axes, B = 0 first) holds the points whose cell coordinate is n
//     (the far boundary) exactly on the axes of B; there the offset is 0 on those axes.
//     Inside a block the points are ordered by the Morton code of their cell coordinates on the
//     free axes (bits interleaved x, y, z, from the lowest), and inside a cell by the bit mask of
//     their odd axes. Block 0 is therefore plain z-order over the interior cells.
// So a level's points are contiguous, its interior ones in z-order, and the split-edge endpoints
// of every point have smaller indices (they are coarser): a decoder that walks H upwards always
// has the predictors it needs.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/leb/leb_grid.h"

namespace voxref::ref {

class HzOrder {
 public:
  explicit HzOrder(const LebGrid& grid);

  const LebGrid& grid() const { return grid_; }
  std::uint64_t size() const { return grid_.pointCount(); }
  // First index of level L (L = -1 gives 0, the corners; L = levelCount() gives size()).
  std::uint64_t levelBegin(int level) const { return levelBegin_[static_cast<std::size_t>(level + 1)]; }

  // The index of p (inside the grid; throws std::invalid_argument otherwise) and its inverse
  // (throws std::out_of_range for H >= size()).
  std::uint64_t index(const GridPoint& p) const;
  GridPoint point(std::uint64_t h) const;

 private:
  friend class HzCursor;
  struct Block {
    std::uint64_t begin = 0;  // first index
    std::uint64_t cells = 0;  // cells in the block (0 when no orientation is allowed)
    int freeAxes = 0;         // axes not on the far boundary (cell coordinate in [0, n))
    unsigned freeMask = 0;
    std::vector<unsigned> orientations;  // odd-axis masks allowed in this block, ascending
  };
  struct Level {
    int scaleLog2 = 0;
    int oddCount = 0;
    int cellBits = 0;  // log2 n
    Block blocks[8];
  };
  LebGrid grid_;
  std::vector<std::uint64_t> levelBegin_;
  std::vector<Level> levels_;
};

// Walks the grid points in H order from a start index, one step at a time, without the cost of
// inverting every index (used by the codec's page loops). Same points as HzOrder::point.
class HzCursor {
 public:
  HzCursor(const HzOrder& order, std::uint64_t start);
  std::uint64_t index() const { return h_; }
  const GridPoint& point() const { return p_; }
  bool done() const { return h_ >= order_->size(); }
  inline void next();
  // The class of point() (as classifyPoint gives it): level -1 for a root corner.
  int level() const { return level_; }
  int scaleLog2() const { return level_ < 0 ? order_->grid_.k : lv().scaleLog2; }
  unsigned oddAxes() const { return level_ < 0 ? 0u : blk().orientations[orientation_]; }

 private:
  const HzOrder::Level& lv() const { return order_->levels_[static_cast<std::size_t>(level_)]; }
  const HzOrder::Block& blk() const { return lv().blocks[block_]; }
  inline void computeCell();
  inline void computePoint();
  const HzOrder* order_;
  std::uint64_t h_;
  GridPoint p_{0, 0, 0};
  int level_ = -1, block_ = 0;
  std::uint64_t cell_ = 0;  // Morton code of the cell inside the block
  std::size_t orientation_ = 0;
  GridPoint cellBase_{0, 0, 0};  // the cell's corner (its coordinates times the cell side)
};

namespace hz_detail {
// Spreads the low 21 bits of v so that bit i lands on bit 3i (and back); the classic magic masks.
inline std::uint64_t spread3(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}
inline std::uint64_t compact3(std::uint64_t v) {
  v &= 0x1249249249249249ULL;
  v = (v ^ (v >> 2)) & 0x10c30c30c30c30c3ULL;
  v = (v ^ (v >> 4)) & 0x100f00f00f00f00fULL;
  v = (v ^ (v >> 8)) & 0x1f0000ff0000ffULL;
  v = (v ^ (v >> 16)) & 0x1f00000000ffffULL;
  v = (v ^ (v >> 32)) & 0x1fffff;
  return v;
}
inline std::uint64_t spread2(std::uint64_t v) {
  v &= 0xffffffff;
  v = (v | v << 16) & 0x0000ffff0000ffffULL;
  v = (v | v << 8) & 0x00ff00ff00ff00ffULL;
  v = (v | v << 4) & 0x0f0f0f0f0f0f0f0fULL;
  v = (v | v << 2) & 0x3333333333333333ULL;
  v = (v | v << 1) & 0x5555555555555555ULL;
  return v;
}
inline std::uint64_t compact2(std::uint64_t v) {
  v &= 0x5555555555555555ULL;
  v = (v ^ (v >> 1)) & 0x3333333333333333ULL;
  v = (v ^ (v >> 2)) & 0x0f0f0f0f0f0f0f0fULL;
  v = (v ^ (v >> 4)) & 0x00ff00ff00ff00ffULL;
  v = (v ^ (v >> 8)) & 0x0000ffff0000ffffULL;
  v = (v ^ (v >> 16)) & 0xffffffff;
  return v;
}
}  // namespace hz_detail

// Morton code of `count` (0..3) coordinates of at most 21 bits, coordinate 0 in the lowest bit;
// and its inverse.
inline std::uint64_t mortonEncode(const int* c, int count) {
  using namespace hz_detail;
  switch (count) {
    case 3:
      return spread3(static_cast<std::uint64_t>(c[0])) | spread3(static_cast<std::uint64_t>(c[1])) << 1 |
             spread3(static_cast<std::uint64_t>(c[2])) << 2;
    case 2:
      return spread2(static_cast<std::uint64_t>(c[0])) | spread2(static_cast<std::uint64_t>(c[1])) << 1;
    case 1:
      return static_cast<std::uint64_t>(c[0]);
    default:
      return 0;
  }
}
inline void mortonDecode(std::uint64_t code, int count, int* c) {
  using namespace hz_detail;
  switch (count) {
    case 3:
      c[0] = static_cast<int>(compact3(code));
      c[1] = static_cast<int>(compact3(code >> 1));
      c[2] = static_cast<int>(compact3(code >> 2));
      break;
    case 2:
      c[0] = static_cast<int>(compact2(code));
      c[1] = static_cast<int>(compact2(code >> 1));
      break;
    case 1:
      c[0] = static_cast<int>(code);
      break;
    default:
      break;
  }
}

inline void HzCursor::computeCell() {
  const HzOrder::Level& level = lv();
  const HzOrder::Block& b = level.blocks[block_];
  int free[3] = {0, 0, 0};
  mortonDecode(cell_, b.freeAxes, free);
  const int side = 2 << level.scaleLog2;  // of a cell
  const int n = 1 << level.cellBits;
  int f = 0;
  for (int a = 0; a < 3; ++a) cellBase_[a] = (((b.freeMask >> a) & 1) ? free[f++] : n) * side;
}

inline void HzCursor::computePoint() {
  if (level_ < 0) {
    const int n = order_->grid_.side();
    p_ = {(cell_ & 1) ? n : 0, (cell_ & 2) ? n : 0, (cell_ & 4) ? n : 0};
    return;
  }
  const int h = 1 << lv().scaleLog2;
  const unsigned odd = blk().orientations[orientation_];
  for (int a = 0; a < 3; ++a) p_[a] = cellBase_[a] + (((odd >> a) & 1) ? h : 0);
}

inline void HzCursor::next() {
  ++h_;
  if (h_ >= order_->size()) return;
  if (level_ < 0) {
    if (++cell_ < 8) return computePoint();
    level_ = 0;
    block_ = 0;
    cell_ = 0;
    orientation_ = 0;
  } else if (++orientation_ < blk().orientations.size()) {
    return computePoint();  // another point of the same cell
  } else {
    orientation_ = 0;
    ++cell_;
  }
  // Move on while the current block is exhausted (blocks may be empty).
  while (cell_ >= blk().cells) {
    cell_ = 0;
    orientation_ = 0;
    if (++block_ == 8) {
      block_ = 0;
      ++level_;
    }
  }
  computeCell();
  computePoint();
}

}  // namespace voxref::ref
