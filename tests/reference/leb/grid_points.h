// Test helper: the points of an LEB grid as a range (z slowest, then y, then x), every point or
// only the diamonds' split vertices (all but the 8 root corners), and the mesh with every diamond
// split; shared by the grid, mesh, bounds and extraction tests. A range keeps a test's control
// flow (continue, ASSERT_* returning from the test) as a loop of its own would.
#pragma once

#include <cstddef>
#include <iterator>

#include "reference/leb/diamond_mesh.h"
#include "reference/leb/leb_grid.h"

namespace voxref::ref::test_support {

class GridPoints {
 public:
  GridPoints(const LebGrid& g, bool diamondsOnly) : g_(&g), diamondsOnly_(diamondsOnly) {}

  class Iterator {
   public:
    using value_type = GridPoint;
    using difference_type = std::ptrdiff_t;
    Iterator(const LebGrid* g, bool diamondsOnly, GridPoint p) : g_(g), diamondsOnly_(diamondsOnly), p_(p) {
      skipCorners();
    }
    const GridPoint& operator*() const { return p_; }
    Iterator& operator++() {
      step();
      skipCorners();
      return *this;
    }
    bool operator==(const Iterator& o) const { return p_ == o.p_; }

   private:
    void step() {
      const int n = g_->side();
      if (++p_[0] <= n) return;
      p_[0] = 0;
      if (++p_[1] <= n) return;
      p_[1] = 0;
      ++p_[2];
    }
    void skipCorners() {
      while (diamondsOnly_ && p_[2] <= g_->side() && isRootCorner(*g_, p_)) step();
    }
    const LebGrid* g_;
    bool diamondsOnly_;
    GridPoint p_;
  };

  Iterator begin() const { return {g_, diamondsOnly_, {0, 0, 0}}; }
  Iterator end() const { return {g_, false, {0, 0, g_->side() + 1}}; }

 private:
  const LebGrid* g_;
  bool diamondsOnly_;
};

// Every point of the grid.
inline GridPoints gridPoints(const LebGrid& g) { return {g, false}; }
// Every split vertex of a diamond: every point but the root corners.
inline GridPoints diamondPoints(const LebGrid& g) { return {g, true}; }

// The mesh with every diamond split, split in diamondPoints' order.
inline DiamondMesh fullyRefined(const LebGrid& g) {
  DiamondMesh mesh(g);
  for (const GridPoint& d : diamondPoints(g)) mesh.split(d);
  return mesh;
}

}  // namespace voxref::ref::test_support
