#include "reference/iso/tiered_bounds.h"

#include <bit>
#include <stdexcept>
#include <string>

namespace voxref::ref {
namespace {

bool isFinest(const GridPoint& p) { return ((p[0] | p[1] | p[2]) & 1) != 0; }

template <class T>
CoarseDiamondBounds computeCoarse(const LebGrid& grid, std::span<const T> values, int threads,
                                  const std::function<void(double)>& progress) {
  requireIndexedGrid(grid, "coarse diamond bounds");
  if (values.size() != grid.pointCount())
    throw std::invalid_argument("coarse diamond bounds: " + std::to_string(values.size()) + " values for a grid of " +
                                std::to_string(grid.pointCount()) + " points");
  CoarseDiamondBounds b;
  b.grid = grid;
  const auto n = static_cast<std::uint64_t>(b.halfPointsPerAxis());
  b.assign(n * n * n);
  // The finest scale fills the last three levels (leb_grid.h: level 3 (k - 1 - s) + 2 - phase).
  const int stored = grid.levelCount() - 4;
  if (stored < 0) return b;
  auto valueAt = [&](const GridPoint& q) { return static_cast<int>(values[grid.linearIndex(q)]); };
  const HzOrder order(grid);
  forLevelsFinestFirst(
      order, stored, threads,
      [&](const HzCursor& c, int) {
        const GridPoint& p = c.point();
        const DiamondRange r = foldDiamond(grid, p, c.scaleLog2(), c.oddAxes(), true, valueAt, [&](const GridPoint& q) {
          if (isFinest(q)) return finestDiamondRange(grid, q, valueAt);
          return b.at(b.indexOf(q));
        });
        b.store(b.indexOf(p), r);
      },
      progress);
  return b;
}

}  // namespace

CoarseDiamondBounds computeCoarseDiamondBounds(const LebGrid& grid, std::span<const std::uint16_t> values, int threads,
                                               const std::function<void(double)>& progress) {
  return computeCoarse(grid, values, threads, progress);
}

CoarseDiamondBounds computeCoarseDiamondBounds(const LebGrid& grid, std::span<const std::uint8_t> values, int threads,
                                               const std::function<void(double)>& progress) {
  return computeCoarse(grid, values, threads, progress);
}

TieredDiamondBounds::TieredDiamondBounds(const CoarseDiamondBounds& coarse, GridField& field, std::size_t memoEntries)
    : coarse_(&coarse), field_(&field), memo_(std::bit_floor(std::max<std::size_t>(memoEntries, 1))) {
  if (field.grid().k != coarse.grid.k)
    throw std::invalid_argument("tiered diamond bounds: the field's grid (k = " + std::to_string(field.grid().k) +
                                ") is not the table's (k = " + std::to_string(coarse.grid.k) + ")");
  mask_ = memo_.size() - 1;
}

DiamondRange TieredDiamondBounds::rangeOf(const GridPoint& p) const {
  if (!isFinest(p)) return coarse_->at(coarse_->indexOf(p));
  const std::uint64_t key = coarse_->grid.linearIndex(p);
  Memo& m = memo_[key & mask_];
  if (m.key != key) {
    m.range =
        finestDiamondRange(coarse_->grid, p, [&](const GridPoint& q) { return static_cast<int>(field_->at(q).value); });
    m.key = key;
  }
  return m.range;
}

bool TieredDiamondBounds::mayContain(const GridPoint& p, double isovalue) const {
  const DiamondRange r = rangeOf(p);
  return r.min <= isovalue && isovalue <= r.max;
}

float TieredDiamondBounds::errorOf(const GridPoint& p) const { return rangeOf(p).error; }

}  // namespace voxref::ref
