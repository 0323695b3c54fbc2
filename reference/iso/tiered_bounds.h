// Diamond bounds in an eighth of the memory: a table for the diamonds of scale 2 and coarser
// (split vertices with even coordinates only, one grid point in eight) and the finest diamonds
// computed from the field when asked (diamond_range.h), kept in a small direct-mapped
// memo. The answers are those of the full table (diamond_bounds.h), bit for bit, so refinement
// and extraction make the same meshes with either.
//
// Memory: 8 bytes per point of the half grid ((2^(k-1) + 1)^3 points; 1.08 GB for the 1025^3
// grid, against 8.6 GB for the full table) and 24 bytes per memo entry. A finest diamond's range
// reads about thirty values of the field, through its own cache (CompressedGridField).
// Not thread safe: the memo and the field are changed by queries (refinement and extraction are
// single-threaded).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "reference/iso/diamond_bounds.h"
#include "reference/iso/diamond_range.h"
#include "reference/iso/grid_field.h"

namespace voxref::ref {

// The table part: entries of the points with even coordinates, indexed by the linear index of
// p / 2 in a grid of side 2^(k-1) (computeDiamondBounds's entries at those points; the root
// corners hold zeros).
struct CoarseDiamondBounds : DiamondRangeTable {
  LebGrid grid;

  int halfPointsPerAxis() const { return grid.side() / 2 + 1; }
  std::uint64_t indexOf(const GridPoint& p) const {
    const auto n = static_cast<std::uint64_t>(halfPointsPerAxis());
    return static_cast<std::uint64_t>(p[0] / 2) +
           n * (static_cast<std::uint64_t>(p[1] / 2) + n * static_cast<std::uint64_t>(p[2] / 2));
  }
};

// From the field's values at every grid point in LebGrid::linearIndex order (for a volume whose
// extents are the grid's points per axis, the volume itself, x fastest), 16 or 8 bits. Reads every
// value about four times and holds nothing but the table; level by level from the finest stored
// one, in parallel, the same for every thread count. progress(fraction) is called as it goes
// (optional). Throws std::invalid_argument when values has not grid.pointCount() entries.
CoarseDiamondBounds computeCoarseDiamondBounds(const LebGrid& grid, std::span<const std::uint16_t> values,
                                               int threads = 0, const std::function<void(double)>& progress = {});
CoarseDiamondBounds computeCoarseDiamondBounds(const LebGrid& grid, std::span<const std::uint8_t> values,
                                               int threads = 0, const std::function<void(double)>& progress = {});

class TieredDiamondBounds final : public DiamondRanges {
 public:
  // The field gives the finest diamonds' values: the field the table was computed from (a
  // DenseGridField, or a CompressedGridField of its stream: the same values). Both must outlive
  // this object. Throws std::invalid_argument when the field's grid is not the table's.
  TieredDiamondBounds(const CoarseDiamondBounds& coarse, GridField& field, std::size_t memoEntries = 1u << 16);

  const LebGrid& lebGrid() const override { return coarse_->grid; }
  bool mayContain(const GridPoint& p, double isovalue) const override;
  float errorOf(const GridPoint& p) const override;
  // The entry of any diamond (not a root corner).
  DiamondRange rangeOf(const GridPoint& p) const;

 private:
  struct Memo {
    std::uint64_t key = ~std::uint64_t{0};
    DiamondRange range;
  };
  const CoarseDiamondBounds* coarse_;
  GridField* field_;
  mutable std::vector<Memo> memo_;
  std::uint64_t mask_ = 0;
};

}  // namespace voxref::ref
