#include "reference/iso/diamond_bounds.h"

#include <algorithm>
#include <cmath>

#include "reference/common/parallel.h"
#include "reference/leb/hz_order.h"

namespace voxref::ref {

DiamondBounds computeDiamondBounds(const LebGrid& grid, const std::vector<std::uint16_t>& values, int threads) {
  DiamondBounds b;
  b.grid = grid;
  const std::uint64_t n = grid.pointCount();
  b.min.assign(n, 0);
  b.max.assign(n, 0);
  b.error.assign(n, 0.0f);
  const HzOrder order(grid);
  constexpr std::uint64_t kChunk = 1u << 14;
  for (int level = grid.levelCount() - 1; level >= 0; --level) {
    const std::uint64_t begin = order.levelBegin(level), end = order.levelBegin(level + 1);
    const int chunks = static_cast<int>((end - begin + kChunk - 1) / kChunk);
    parallelFor(chunks, threads, [&](int chunk) {
      const std::uint64_t first = begin + static_cast<std::uint64_t>(chunk) * kChunk;
      const std::uint64_t last = std::min(end, first + kChunk);
      HzCursor c(order, first);
      for (; c.index() < last; c.next()) {
        const GridPoint& p = c.point();
        const std::uint64_t i = grid.linearIndex(p);
        const SplitEdge e = splitEdgeOf(p, c.scaleLog2(), c.oddAxes());
        const int va = values[grid.linearIndex(e.a)], vb = values[grid.linearIndex(e.b)], vp = values[i];
        int lo = std::min({va, vb, vp}), hi = std::max({va, vb, vp});
        for (const GridPoint& r : diamondRing(grid, p)) {
          const int v = values[grid.linearIndex(r)];
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        float err = static_cast<float>(std::abs(2 * vp - va - vb)) / 2.0f;
        if (level + 1 < grid.levelCount())
          for (const GridPoint& child : diamondChildren(grid, p)) {
            const std::uint64_t j = grid.linearIndex(child);
            lo = std::min<int>(lo, b.min[j]);
            hi = std::max<int>(hi, b.max[j]);
            err = std::max(err, b.error[j]);
          }
        b.min[i] = static_cast<std::uint16_t>(lo);
        b.max[i] = static_cast<std::uint16_t>(hi);
        b.error[i] = err;
      }
    });
  }
  return b;
}

GridBox diamondBox(const LebGrid& grid, const GridPoint& p) {
  const SplitEdge e = splitEdge(grid, p);
  GridBox box{p, p};
  auto add = [&](const GridPoint& q) {
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = std::min(box.lo[a], q[a]);
      box.hi[a] = std::max(box.hi[a], q[a]);
    }
  };
  add(e.a);
  add(e.b);
  for (const GridPoint& r : diamondRing(grid, p)) add(r);
  return box;
}

}  // namespace voxref::ref
