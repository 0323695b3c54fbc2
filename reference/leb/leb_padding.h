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
// Memory: size() entries, at most shellPoints(grid, dims), each at most kBytesPerPoint.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

#include "reference/common/flat_u64_map.h"
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
  // in the padding the value this map holds (a coarser level, already added).
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
  const LebValues& at(const GridPoint& q) const;
  std::size_t size() const { return values_.size(); }

  // The number of shell points, from the extents alone (a closed form per level and orientation).
  static std::uint64_t shellPoints(const LebGrid& grid, const Dims3& dims);
  // An upper bound on one entry's memory, for the bounds: the table is reserved for the whole
  // shell, so at most 4 slots of a key and the values (flat_u64_map.h), and it never doubles.
  static constexpr std::uint64_t kBytesPerPoint = 4 * (8 + sizeof(LebValues));

 private:
  // Calls f(p, scaleLog2, oddAxes) for every shell point of `level`.
  template <class F>
  void forEachShellPoint(int level, F&& f) const;

  LebGrid grid_;
  Dims3 dims_;
  int components_;
  FlatU64Map<LebValues> values_;  // by linearIndex, reserved for the whole shell
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
    values_.try_emplace(grid_.linearIndex(p), predictPoint(p, level, scaleLog2, odd, components_,
                                                           [&](const GridPoint& q) { return valuesAt(q, inside); }));
  });
}

}  // namespace voxref::ref
