// The per-diamond range and error of diamond_bounds.h (Gregorski et al. 2004, section 4) as one
// rule (foldDiamond) for every way they are held, and for a diamond of the finest scale (h = 1: a
// split vertex with an odd coordinate) computed from the field where it is asked for instead of
// stored. Seven eighths of the grid's
// points are such diamonds; computing them costs a few dozen value reads, and keeping them out of
// the table is what lets the bounds of a 1025^3 grid fit in memory (tiered_bounds.h).
//
// The entry is, as in computeDiamondBounds, the range of the values at the split vertex, the
// split-edge endpoints and the ring of the diamond and of every descendant (children,
// recursively), and the largest |v(x) - (v(a) + v(b)) / 2| over their split edges: exactly the
// same numbers, not a looser bound. Away from the grid's faces the points and edges involved form
// a fixed stencil per residue of p modulo 4 (the LEB hierarchy of the finest scale repeats with
// period 4: leb_grid.h, the parent cube has side 4h), derived once by walking the hierarchy of a
// small grid; within kFinestStencilReach of a face the hierarchy is walked for p itself.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <vector>

#include "reference/common/parallel.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_grid.h"

namespace voxref::ref {

struct DiamondRange {
  int min = 0, max = 0;
  float error = 0.0f;  // a multiple of one half, exact
};

// Entries stored 8 bytes each, 16-bit min and max and the error: the layout of the full table
// (diamond_bounds.h) and of the coarse one (tiered_bounds.h), indexed as each of them says.
struct DiamondRangeTable {
  std::vector<std::uint16_t> min, max;
  std::vector<float> error;

  void assign(std::uint64_t entries) {
    min.assign(entries, 0);
    max.assign(entries, 0);
    error.assign(entries, 0.0f);
  }
  DiamondRange at(std::uint64_t i) const { return {min[i], max[i], error[i]}; }
  // r.min and r.max are values of a 16-bit field.
  void store(std::uint64_t i, const DiamondRange& r) {
    min[i] = static_cast<std::uint16_t>(r.min);
    max[i] = static_cast<std::uint16_t>(r.max);
    error[i] = r.error;
  }
};

// The entry of diamond p (scale 2^scaleLog2, odd axes oddAxes; children when hasChildren) from
// the values at its split vertex, split-edge endpoints and ring and its children's entries
// (childRange(q)): the rule of diamond_bounds.h, for every way the entries are held.
template <class ValueAt, class ChildRange>
DiamondRange foldDiamond(const LebGrid& g, const GridPoint& p, int scaleLog2, unsigned oddAxes, bool hasChildren,
                         ValueAt&& valueAt, ChildRange&& childRange) {
  const SplitEdge e = splitEdgeOf(p, scaleLog2, oddAxes);
  const int va = valueAt(e.a), vb = valueAt(e.b), vp = valueAt(p);
  DiamondRange r{std::min({va, vb, vp}), std::max({va, vb, vp}), static_cast<float>(std::abs(2 * vp - va - vb)) / 2.0f};
  for (const GridPoint& q : diamondRing(g, p)) {
    const int v = valueAt(q);
    r.min = std::min(r.min, v);
    r.max = std::max(r.max, v);
  }
  if (hasChildren)
    for (const GridPoint& child : diamondChildren(g, p)) {
      const DiamondRange c = childRange(child);
      r.min = std::min(r.min, c.min);
      r.max = std::max(r.max, c.max);
      r.error = std::max(r.error, c.error);
    }
  return r;
}

// Calls fn(cursor, level) for every point of the levels fromLevel, fromLevel - 1, ..., 0 in turn
// (finest first: a level's entries need only finer ones), the points of one level in chunks over
// up to `threads` threads (parallel.h: the same results for every count). progress(fraction of the
// points done) after each chunk, when given.
template <class Fn>
void forLevelsFinestFirst(const HzOrder& order, int fromLevel, int threads, Fn&& fn,
                          const std::function<void(double)>& progress = {}) {
  constexpr std::uint64_t kChunk = 1u << 14;
  const double total = static_cast<double>(order.levelBegin(fromLevel + 1) - order.levelBegin(0));
  double before = 0.0;
  for (int level = fromLevel; level >= 0; --level) {
    const std::uint64_t begin = order.levelBegin(level), end = order.levelBegin(level + 1);
    const int chunks = static_cast<int>((end - begin + kChunk - 1) / kChunk);
    parallelFor(
        chunks, threads,
        [&](int chunk) {
          const std::uint64_t first = begin + static_cast<std::uint64_t>(chunk) * kChunk;
          const std::uint64_t last = std::min(end, first + kChunk);
          for (HzCursor c(order, first); c.index() < last; c.next()) fn(c, level);
        },
        [&](int done) {
          if (progress) progress((before + std::min<double>(static_cast<double>(done) * kChunk, end - begin)) / total);
        });
    before += static_cast<double>(end - begin);
  }
}

// Calls point(q) for the split vertex, the split-edge endpoints and the ring of diamond p and of
// each of its descendants, and edge(x, a, b) for the split edge (vertex x, endpoints a, b) of
// each; a point or edge shared by several comes once per diamond. The points and edges whose
// values computeDiamondBounds folds into p's entry, level by level.
template <class Point, class Edge>
void forDiamondAndDescendants(const LebGrid& g, const GridPoint& p, Point&& point, Edge&& edge) {
  const LebPointClass c = classifyPoint(g, p);
  const SplitEdge e = splitEdgeOf(p, c.scaleLog2, c.oddAxes);
  point(p);
  point(e.a);
  point(e.b);
  for (const GridPoint& r : diamondRing(g, p)) point(r);
  edge(p, e.a, e.b);
  if (c.level + 1 < g.levelCount())
    for (const GridPoint& child : diamondChildren(g, p)) forDiamondAndDescendants(g, child, point, edge);
}

// The points (offsets from p) and edges (indices into them) of a finest-scale diamond away from
// the faces, for one residue of p modulo 4.
struct FinestStencil {
  std::vector<std::array<int, 3>> offsets;
  std::vector<std::array<std::uint8_t, 3>> edges;  // vertex, endpoint a, endpoint b
};
// The largest |offset| of any stencil on any axis: a point at least this far from every face of
// the grid uses its stencil.
inline constexpr int kFinestStencilReach = 2;
// The stencil of the points with these residues modulo 4 (at least one odd: a finest-scale point).
const FinestStencil& finestStencil(const std::array<int, 3>& residues);

// The range and error of the finest-scale diamond p (p inside g, with an odd coordinate); valueAt(q)
// gives the field's value at grid point q. Equal to computeDiamondBounds's entry for p.
template <class ValueAt>
DiamondRange finestDiamondRange(const LebGrid& g, const GridPoint& p, ValueAt&& valueAt) {
  const int n = g.side();
  const bool inner =
      std::min({p[0], p[1], p[2]}) >= kFinestStencilReach && std::max({p[0], p[1], p[2]}) <= n - kFinestStencilReach;
  int lo = 1 << 30, hi = -1, twiceError = 0;
  if (inner) {
    const FinestStencil& s = finestStencil({p[0] & 3, p[1] & 3, p[2] & 3});
    std::array<int, 125> v;  // a stencil lies within +-kFinestStencilReach
    for (std::size_t i = 0; i < s.offsets.size(); ++i) {
      const std::array<int, 3>& o = s.offsets[i];
      v[i] = valueAt(GridPoint{p[0] + o[0], p[1] + o[1], p[2] + o[2]});
      lo = std::min(lo, v[i]);
      hi = std::max(hi, v[i]);
    }
    for (const auto& e : s.edges) twiceError = std::max(twiceError, std::abs(2 * v[e[0]] - v[e[1]] - v[e[2]]));
  } else {
    forDiamondAndDescendants(
        g, p,
        [&](const GridPoint& q) {
          const int x = valueAt(q);
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        },
        [&](const GridPoint& x, const GridPoint& a, const GridPoint& b) {
          twiceError = std::max(twiceError, std::abs(2 * valueAt(x) - valueAt(a) - valueAt(b)));
        });
  }
  return {lo, hi, static_cast<float>(twiceError) / 2.0f};
}

}  // namespace voxref::ref
