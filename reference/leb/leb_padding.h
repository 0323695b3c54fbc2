// The padding an LEB codec needs, and no more (Gregorski et al. 2004, section 3.1; FORMAT.md,
// "Prediction"): a point of the grid outside the volume is not coded, its value is its
// prediction, and it matters only where a prediction of a point inside the volume reaches it.
//
// Which padding points a prediction can reach: the split-edge endpoints of a point of scale h lie
// h from it along its odd axes (leb_grid.h), where its coordinates are odd multiples of h, so
// both endpoints have scale at least 2h. A chain of endpoints from a point inside the volume to a
// padding point q of scale H therefore moves, on every axis, at most h0 + h1 + ... + h_m with
// each term at most half the next and h_m <= H / 2: less than H. So q lies less than H beyond the
// volume on every axis, q_a <= X_a + H - 2 (X_a the extent): the *shell* of scale H. The codec
// keeps the shell's values, level by level, and computes nothing else of the padding; a 1025x1x1
// volume in its 1025^3 grid keeps a few thousand of the grid's 10^9 padding points.
//
// The shell's layout: a padding point q of scale H lies beyond the volume on the axes of its
// *outside set* (q_a >= X_a), and there q_a is the first multiple of H at or past X_a, the only one
// up to X_a + H - 2 (a root corner: the grid's side). So the shell's points of one scale and one
// outside set lie on one face, edge or corner of the volume's box, in a lattice of step H, and the
// table keeps each such block dense, indexed by q_a / H on the other axes: a lookup computes its
// entry's place, and points next to each other in the volume read entries next to each other.
// The blocks also hold the lattice's points of coarser scale, never read: where a block's pinned
// coordinates are multiples of 2H, a quarter of a face's entries (about 4/3 of an entry a shell
// point in large volumes), and on an edge of one or two entries possibly all of them.
//
// Memory: tableBytes(grid, dims), allocated by the constructor, whatever the levels added.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "reference/common/volume.h"
#include "reference/leb/leb_grid.h"
#include "reference/leb/prediction.h"

namespace voxref::ref {

using LebValues = std::array<std::int32_t, 3>;

inline bool insideVolume(const GridPoint& p, const Dims3& d) { return p[0] < d[0] && p[1] < d[1] && p[2] < d[2]; }
inline std::size_t volumeIndex(const GridPoint& p, const Dims3& d) {
  return static_cast<std::size_t>(p[0]) +
         static_cast<std::size_t>(d[0]) * (static_cast<std::size_t>(p[1]) + static_cast<std::size_t>(d[1]) * p[2]);
}

// The prediction of p (of `level`, scale 2^scaleLog2, odd axes `oddAxes`: classifyPoint or an
// HzOrder walk gives them) for `components` components, equation 1 on its split edge; a root
// corner (level -1) is predicted as 0. valuesAt(q) gives the components at endpoint q (a padding
// point's in one lookup of the shell).
template <class ValuesAt>
[[gnu::always_inline]] inline LebValues predictPoint(const GridPoint& p, int level, int scaleLog2, unsigned oddAxes,
                                                     int components, ValuesAt&& valuesAt) {
  LebValues pred{0, 0, 0};
  if (level < 0) return pred;
  const SplitEdge e = splitEdgeOf(p, scaleLog2, oddAxes);
  const LebValues a = valuesAt(e.a), b = valuesAt(e.b);
  for (std::size_t k = 0; k < static_cast<std::size_t>(components); ++k) pred[k] = predictMidpoint(a[k], b[k]);
  return pred;
}

class LebPadding {
 public:
  LebPadding(const LebGrid& grid, const Dims3& dims, int components);

  // Adds the shell's points of `level` (-1, the root corners, first; then 0, 1, ... in order),
  // each its prediction. An endpoint inside the volume has the value inside(volumeIndex, k), one
  // in the padding the value this table holds (a coarser level, already added).
  template <class Inside>
  void addLevel(int level, Inside&& inside);

  // The components at grid point q: inside(volumeIndex, k) for each k inside the volume, else the
  // shell's values. Throws std::logic_error for a padding point outside the shell (which the bound
  // above excludes: reaching one is a defect of the codec, never of a stream).
  template <class Inside>
  [[gnu::always_inline]] LebValues valuesAt(const GridPoint& q, Inside&& inside) const {
    if (!insideVolume(q, dims_)) return at(q);
    LebValues r{0, 0, 0};
    const std::size_t vi = volumeIndex(q, dims_);
    for (int k = 0; k < components_; ++k) r[static_cast<std::size_t>(k)] = inside(vi, k);
    return r;
  }
  // Throws std::logic_error also for a shell point of a level not added yet.
  const LebValues& at(const GridPoint& q) const {
    const Entry* e = find(q);
    if (!e || !e->added) outsideShell(q);
    return e->values;
  }
  // The shell's points added so far.
  std::size_t size() const { return added_; }

  // The number of shell points, from the extents alone (a closed form per level and orientation).
  static std::uint64_t shellPoints(const LebGrid& grid, const Dims3& dims);
  // The bytes the constructor allocates (the blocks and their entries, from the extents alone), for
  // the memory bounds: 16 bytes an entry, about 4/3 of an entry a shell point in large volumes
  // (0.71 MB for 256x256x128, 16.8 MB for 1024^3).
  static std::uint64_t tableBytes(const LebGrid& grid, const Dims3& dims);
  // What this table allocated: tableBytes of its grid and extents.
  std::uint64_t allocatedBytes() const { return bytesOf(blocks_.size(), entries_.size()); }

 private:
  struct Entry {
    LebValues values{};
    std::uint32_t added = 0;
  };
  // A block of the table: the shell's points of one scale H = 2^s and one outside set m, at
  // entries first + sum over the other axes a of (q_a >> s) * stride[a]; pinned[a] is q_a on the
  // axes of m. Empty (no points) where count is 0.
  struct Block {
    std::uint64_t first = 0, count = 0;
    std::array<std::uint64_t, 3> stride{};
    std::array<int, 3> pinned{};
  };
  // The blocks of every scale 2^s (s = 0..k) and outside set m (1..7), at 8 s + m, packed from 0;
  // none for a volume that fills its grid.
  static std::vector<Block> layout(const LebGrid& grid, const Dims3& dims);
  static std::uint64_t entryCount(const std::vector<Block>& blocks);
  static std::uint64_t bytesOf(std::uint64_t blocks, std::uint64_t entries) {
    return blocks * sizeof(Block) + entries * sizeof(Entry);
  }
  // q's entry, or null where q lies outside the shell (or inside the volume).
  [[gnu::always_inline]] const Entry* find(const GridPoint& q) const {
    const std::ptrdiff_t i = indexOf(q);
    return i < 0 ? nullptr : &entries_[static_cast<std::size_t>(i)];
  }
  [[gnu::always_inline]] std::ptrdiff_t indexOf(const GridPoint& q) const {
    unsigned m = 0;
    int s = grid_.k;
    for (int a = 0; a < 3; ++a) {
      m |= static_cast<unsigned>(q[a] >= dims_[a]) << a;
      s = std::min(s, std::countr_zero(static_cast<unsigned>(q[a])));  // 0 has 32 zeros: never the least
    }
    if (m == 0) return -1;  // inside the volume (always, when the volume fills its grid and blocks_ is empty)
    const Block& b = blocks_[8 * static_cast<std::size_t>(s) + m];
    std::uint64_t i = b.first;
    for (int a = 0; a < 3; ++a) {
      if (((m >> a) & 1u) && q[a] != b.pinned[a]) return -1;
      i += static_cast<std::uint64_t>(q[a] >> s) * b.stride[a];  // 0 on the pinned axes
    }
    return b.count != 0 ? static_cast<std::ptrdiff_t>(i) : -1;
  }
  [[noreturn]] static void outsideShell(const GridPoint& q);

  // Calls f(p, scaleLog2, oddAxes) for every shell point of `level`.
  template <class F>
  void forEachShellPoint(int level, F&& f) const;

  LebGrid grid_;
  Dims3 dims_;
  int components_;
  std::vector<Block> blocks_;
  std::vector<Entry> entries_;
  std::size_t added_ = 0;
};

template <class F>
void LebPadding::forEachShellPoint(int level, F&& f) const {
  const int side = grid_.side();
  if (level < 0) {
    for (unsigned c = 0; c < 8; ++c) {
      const GridPoint p{(c & 1) ? side : 0, (c & 2) ? side : 0, (c & 4) ? side : 0};
      if (!insideVolume(p, dims_)) f(p, grid_.k, 0u);
    }
    return;
  }
  const int scaleLog2 = grid_.k - 1 - level / 3, oddCount = 3 - level % 3, h = 1 << scaleLog2;
  for (unsigned odd = 1; odd < 8; ++odd) {
    if (std::popcount(odd) != oddCount) continue;
    int first[3], last[3];
    for (int a = 0; a < 3; ++a) {
      first[a] = ((odd >> a) & 1u) ? h : 0;
      last[a] = std::min(side, dims_[a] + h - 2);
    }
    for (int z = first[2]; z <= last[2]; z += 2 * h)
      for (int y = first[1]; y <= last[1]; y += 2 * h) {
        int x = first[0];
        if (y < dims_[1] && z < dims_[2] && x < dims_[0])  // the row crosses the volume: start past it
          x += (dims_[0] - x + 2 * h - 1) / (2 * h) * (2 * h);
        for (; x <= last[0]; x += 2 * h) f(GridPoint{x, y, z}, scaleLog2, odd);
      }
  }
}

template <class Inside>
void LebPadding::addLevel(int level, Inside&& inside) {
  forEachShellPoint(level, [&](const GridPoint& p, int scaleLog2, unsigned odd) {
    const std::ptrdiff_t i = indexOf(p);
    if (i < 0) outsideShell(p);  // a defect of the layout: forEachShellPoint gives shell points
    Entry& e = entries_[static_cast<std::size_t>(i)];
    if (e.added) return;
    e.values =
        predictPoint(p, level, scaleLog2, odd, components_, [&](const GridPoint& q) { return valuesAt(q, inside); });
    e.added = 1;
    ++added_;
  });
}

}  // namespace voxref::ref
