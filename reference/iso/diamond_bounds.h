// Per-diamond bounds for view-dependent isosurface extraction (Gregorski et al. 2004, section 4:
// "for each diamond we precompute the minimum and maximum data values and an isosurface error").
//
// For the diamond with split vertex p (every grid point but the root corners):
//   min, max  the range of the field over the diamond's region at full resolution: the values at
//             its ring, its split edge and p, and the ranges of its children (which cover every
//             finer tetrahedron inside the diamond). Conservative: the true range over the
//             diamond's tetrahedra (piecewise-linear at every resolution) lies inside it.
//   error     the largest |value - linear prediction| over p and every descendant:
//             max(|v(p) - (v(a) + v(b)) / 2|, error of each child), in data units (halves exact).
//             Nested (a diamond's error is at least any child's), so refinement driven by it never
//             splits a child before its parent would want to be split.
// A diamond whose [min, max] does not contain the isovalue holds no surface at any resolution.
// Computed level by level from the finest, in parallel; deterministic for any thread count.
// Memory: 8 bytes per grid point (137 MB for 257^3). Indexed by LebGrid::linearIndex.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "reference/iso/diamond_range.h"
#include "reference/iso/grid_field.h"

namespace voxref::ref {

// What refinement and extraction ask of the bounds, however they are held: the full table
// (DiamondBounds) or a table of the coarser diamonds with the finest computed on demand
// (tiered_bounds.h). Both give the same answers for the same field, bit for bit.
class DiamondRanges {
 public:
  virtual ~DiamondRanges() = default;
  virtual const LebGrid& lebGrid() const = 0;
  // Whether min(p) <= isovalue <= max(p): the diamond may hold the surface.
  virtual bool mayContain(const GridPoint& p, double isovalue) const = 0;
  virtual float errorOf(const GridPoint& p) const = 0;
};

// Entries indexed by LebGrid::linearIndex.
struct DiamondBounds final : DiamondRanges, DiamondRangeTable {
  LebGrid grid;

  const LebGrid& lebGrid() const override { return grid; }
  bool mayContain(const GridPoint& p, double isovalue) const override { return holds(grid.linearIndex(p), isovalue); }
  // Whether entry i's range holds the isovalue (mayContain of the point with linear index i).
  bool holds(std::uint64_t i, double isovalue) const { return min[i] <= isovalue && isovalue <= max[i]; }
  float errorOf(const GridPoint& p) const override { return error[grid.linearIndex(p)]; }
};

// Values of a dense field only (it reads every point): DenseGridField::values().
DiamondBounds computeDiamondBounds(const LebGrid& grid, const std::vector<std::uint16_t>& values, int threads = 0);

// The bounds as bytes stored beside a compressed stream (reference/iso/BOUNDS_FORMAT.md), and back.
// parseDiamondBounds checks the magic, version, grid, exact size, CRC-32 and min <= max, and
// throws StreamError naming the offset and field of the first problem. Memory: 8 bytes per grid
// point, as many as the bytes it is given (12 + 8 n), allocated only after the size the header's k
// implies has been checked against their length: a k = 10 header (8.6 GB of bounds) on a short
// file is refused before anything is allocated.
std::string serializeDiamondBounds(const DiamondBounds& bounds);
DiamondBounds parseDiamondBounds(std::string_view bytes);

// The axis-aligned box of a diamond's vertices (ring, split edge and split vertex), in grid
// coordinates.
struct GridBox {
  GridPoint lo, hi;
};
GridBox diamondBox(const LebGrid& grid, const GridPoint& p);

}  // namespace voxref::ref
