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

#include <algorithm>
#include <array>
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
  // index(p) given p's class (classifyPoint(grid, p), which the caller has already), without
  // classifying p again or checking that it lies inside the grid.
  std::uint64_t index(const GridPoint& p, const LebPointClass& c) const;
  // The indices of q = p - 2h on each axis a (h p's scale), given p's index h and class c (not a
  // root corner), into below[a]; kNoIndex where p[a] < 2h (no such point). q is of p's class, so
  // where both lie in one block q's cell is p's one step down on that axis, a decrement of the
  // Morton code's bits of that axis (no encoding); otherwise index(q, c). Equal to index(q)
  // (hz_order_test checks every point and axis of small grids).
  static constexpr std::uint64_t kNoIndex = ~std::uint64_t{0};
  void indicesBelow(std::uint64_t h, const GridPoint& p, const LebPointClass& c, std::uint64_t below[3]) const;

  // Calls f(h, p, level, scaleLog2, oddAxes) for every grid point p with index h in [begin, end)
  // that lies inside the box [0, dims) (the volume), in increasing h, and for no other point: a
  // block whose far-boundary axes lie outside the box is skipped, and inside a block the Morton
  // tree of its cells is descended with every subtree that lies past the box or outside the
  // range cut off whole. So the work follows the points inside, not the grid: a 1025x1x1
  // volume's 1025 points cost what they are, not the 1025^3 points of the grid. Level -1 (a root
  // corner) comes with scaleLog2 k and no odd axes.
  template <class F>
  void forEachInside(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end, F&& f) const;
  // True only if every grid point with index in [begin, end) lies inside the box [0, dims): then
  // forEachInside would call f for each of them. Conservative: each block's part of the range is
  // bounded by the Morton node of its first and last cells' common prefix, and false may come for a
  // range whose points all lie inside (a caller then walks them). Costs a few operations per level,
  // not per point.
  bool allInside(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end) const;
  // How many grid points with index in [begin, end) lie inside the box [0, dims): the points
  // forEachInside gives (at the cost of allInside where it holds).
  std::uint64_t countInside(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end) const;
  // A group of cells of one level's block, as forEachCellInside gives it: the cells whose Morton
  // codes differ only in their low freeAxes bits (2^freeAxes cells; fewer only in a block of one
  // cell), and those of their points that lie in the range.
  struct CellGroup {
    static constexpr int kMaxPoints = 24;  // 8 cells of 3 points
    std::uint64_t h;                       // the index of point `first`
    GridPoint base;                        // the corner of cell 0 (its low code bits zero)
    int level, scaleLog2;
    int freeAxes;         // bit i of a cell's number j moves it by 2^(scaleLog2 + 1) on axis[i]
    const int* axis;      // (mortonEncode's order); the other axes hold the grid's far side
    const unsigned* odd;  // a cell's points by their odd axes, in index order
    int orientations;     // how many points a cell has
    int first, last;      // point q in [first, last): cell q / orientations, odd[q % orientations]
    int fullPoints;       // 2^freeAxes x orientations: last - first for a whole group
    int blockKey;         // the same for the groups of one level's block, and only for them
  };
  // forEachInside by groups of cells, for a range whose points all lie inside the box
  // (allInside(dims, begin, end) is true) and that holds no root corner (begin >= 8): calls
  // f(group) for each group with points in [begin, end), in index order; the group's points in
  // the range have indices group.h, group.h + 1, ...: the points forEachInside gives, in its order.
  // The codec's walk (leb_codec.cpp, encoder and decoder) takes its per-cell work out of the
  // per-point loop this way: a group's points lie at the same offsets from its corner in every
  // group of a block.
  template <class F>
  void forEachCellInside(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end, F&& f) const;

 private:
  friend class HzCursor;
  struct Block;
  struct Level;
  // One block's part of an index range: its level, its cells [mlo, mhi) of the range, its free
  // axes (axis[0..nf)), and whether one of its far-boundary axes lies outside the box.
  struct BlockPart {
    int level;
    const Level& lv;
    const Block& blk;
    std::uint64_t mlo, mhi;
    int axis[3], nf;
    bool boundaryOutside;
  };
  // Calls f(part) for each block with indices in [begin, end) (end at most size()), in index
  // order, while f returns true; returns false when f stopped it.
  template <class F>
  bool forEachBlockPart(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end, F&& f) const;
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
[[gnu::always_inline]] inline void mortonDecode(std::uint64_t code, int count, int* c) {
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

namespace hz_detail {
// The cells of one block under a Morton subtree: the node covers the codes [m0, m0 + 2^(nf r))
// and, on free axis i, the cells c0[i] + [0, 2^r). Bit level t of free coordinate i is bit
// t nf + i of the code (mortonEncode), so child j of a node sets bit r - 1 of coordinate i where
// bit i of j is set, and its codes start at m0 + j 2^(nf (r - 1)).
template <class Leaf>
void mortonDescend(int nf, const int* limit, int r, std::uint64_t m0, const int* c0, std::uint64_t mlo,
                   std::uint64_t mhi, Leaf& leaf) {
  const std::uint64_t span = std::uint64_t{1} << (nf * r);
  if (m0 >= mhi || m0 + span <= mlo) return;
  for (int i = 0; i < nf; ++i)
    if (c0[i] >= limit[i]) return;  // every cell of the node lies past the box on axis i
  if (r == 0) return leaf(m0, c0);
  // A node wholly inside the box and the range: its cells in code order, without descending.
  bool whole = m0 >= mlo && m0 + span <= mhi;
  for (int i = 0; i < nf; ++i) whole = whole && c0[i] + (1 << r) <= limit[i];
  if (whole) {
    for (std::uint64_t m = 0; m < span; ++m) {
      int c[3] = {0, 0, 0};
      mortonDecode(m, nf, c);
      for (int i = 0; i < nf; ++i) c[i] += c0[i];
      leaf(m0 + m, c);
    }
    return;
  }
  const std::uint64_t childSpan = span >> nf;
  for (unsigned j = 0; j < (1u << nf); ++j) {
    int c[3] = {0, 0, 0};
    for (int i = 0; i < nf; ++i) c[i] = c0[i] + static_cast<int>(((j >> i) & 1u) << (r - 1));
    mortonDescend(nf, limit, r - 1, m0 + j * childSpan, c, mlo, mhi, leaf);
  }
}
}  // namespace hz_detail

template <class F>
bool HzOrder::forEachBlockPart(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end, F&& f) const {
  const int side = grid_.side();
  for (int level = 0; level < grid_.levelCount(); ++level) {
    if (levelBegin(level + 1) <= begin) continue;
    if (levelBegin(level) >= end) break;
    const Level& lv = levels_[static_cast<std::size_t>(level)];
    for (unsigned b = 0; b < 8; ++b) {
      const Block& blk = lv.blocks[b];
      const std::uint64_t orientations = blk.orientations.size();
      if (blk.cells == 0 || blk.begin >= end || blk.begin + blk.cells * orientations <= begin) continue;
      BlockPart part{level,
                     lv,
                     blk,
                     begin > blk.begin ? (begin - blk.begin) / orientations : 0,
                     std::min(blk.cells, (end - blk.begin + orientations - 1) / orientations),
                     {0, 0, 0},
                     0,
                     false};
      for (int a = 0; a < 3; ++a) {
        if ((b >> a) & 1u)
          part.boundaryOutside = part.boundaryOutside || side >= dims[static_cast<std::size_t>(a)];
        else
          part.axis[part.nf++] = a;
      }
      if (!f(part)) return false;
    }
  }
  return true;
}

template <class F>
void HzOrder::forEachInside(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end, F&& f) const {
  end = std::min(end, size());
  const int side = grid_.side();
  const auto inside = [&](const GridPoint& p) { return p[0] < dims[0] && p[1] < dims[1] && p[2] < dims[2]; };
  for (std::uint64_t h = begin; h < std::min<std::uint64_t>(end, 8); ++h) {
    const GridPoint p{(h & 1) ? side : 0, (h & 2) ? side : 0, (h & 4) ? side : 0};
    if (inside(p)) f(h, p, -1, grid_.k, 0u);
  }
  forEachBlockPart(dims, begin, end, [&](const BlockPart& part) {
    if (part.boundaryOutside) return true;
    const Level& lv = part.lv;
    const Block& blk = part.blk;
    const std::uint64_t orientations = blk.orientations.size();
    const int scale = 1 << lv.scaleLog2, cellSide = 2 * scale, nf = part.nf;
    int limit[3] = {0, 0, 0};
    for (int i = 0; i < nf; ++i)  // cells c with cellSide c < dims[a]
      limit[i] = (dims[static_cast<std::size_t>(part.axis[i])] + cellSide - 1) / cellSide;
    auto leaf = [&](std::uint64_t m, const int* c) {
      GridPoint base{side, side, side};
      for (int i = 0; i < nf; ++i) base[static_cast<std::size_t>(part.axis[i])] = cellSide * c[i];
      for (std::uint64_t o = 0; o < orientations; ++o) {
        const std::uint64_t h = blk.begin + m * orientations + o;
        if (h < begin) continue;
        if (h >= end) return;
        const unsigned odd = blk.orientations[o];
        GridPoint p = base;
        for (int a = 0; a < 3; ++a) p[a] += ((odd >> a) & 1u) ? scale : 0;
        if (inside(p)) f(h, p, part.level, lv.scaleLog2, odd);
      }
    };
    const int origin[3] = {0, 0, 0};
    hz_detail::mortonDescend(nf, limit, nf == 0 ? 0 : lv.cellBits, 0, origin, part.mlo, part.mhi, leaf);
    return true;
  });
}

template <class F>
void HzOrder::forEachCellInside(const std::array<int, 3>& dims, std::uint64_t begin, std::uint64_t end, F&& f) const {
  end = std::min(end, size());
  const int side = grid_.side();
  forEachBlockPart(dims, begin, end, [&](const BlockPart& part) {
    const Block& blk = part.blk;
    const auto orientations = static_cast<std::uint64_t>(blk.orientations.size());
    const int cellSide = 2 << part.lv.scaleLog2, nf = part.nf;
    const std::uint64_t groupCells = std::uint64_t{1} << nf;
    CellGroup g{0,
                {side, side, side},
                part.level,
                part.lv.scaleLog2,
                nf,
                part.axis,
                blk.orientations.data(),
                static_cast<int>(orientations),
                0,
                0,
                static_cast<int>(groupCells * orientations),
                8 * part.level + static_cast<int>(&blk - part.lv.blocks)};
    for (std::uint64_t m0 = part.mlo & ~(groupCells - 1); m0 < part.mhi; m0 += groupCells) {
      int c[3] = {0, 0, 0};
      mortonDecode(m0, nf, c);
      for (int i = 0; i < nf; ++i) g.base[static_cast<std::size_t>(part.axis[i])] = cellSide * c[i];
      const std::uint64_t h0 = blk.begin + m0 * orientations;  // the group's first point
      g.first = h0 < begin ? static_cast<int>(begin - h0) : 0;
      g.last = static_cast<int>(std::min(std::min(groupCells, blk.cells - m0) * orientations, end - h0));
      g.h = h0 + static_cast<std::uint64_t>(g.first);
      f(static_cast<const CellGroup&>(g));
    }
    return true;
  });
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
