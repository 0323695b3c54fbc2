// A conforming longest-edge-bisection mesh, as a set of split diamonds (Gregorski et al. 2004,
// section 2: "splitting and merging diamonds ensures that the mesh is always crack-free").
//
// Invariant: every parent of a split diamond is split. Then the leaf tetrahedra (the root's six,
// bisected wherever their split vertex's diamond is split) meet face to face: no cracks. split()
// keeps the invariant by splitting missing parents first (recursively); merge() refuses a diamond
// with a split child. Exact integer geometry; not thread-safe. Memory: one bit per grid point
// ((2^k + 1)^3 bits: 2.1 MB at k = 8, 135 MB at k = 10), whatever the number of splits.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "reference/leb/leb_grid.h"

namespace voxref::ref {

struct Tetrahedron {
  std::array<GridPoint, 4> v;
};

// The six tetrahedra of the root cube around its major diagonal (0,0,0)-(N,N,N).
std::array<Tetrahedron, 6> rootTetrahedra(const LebGrid& g);
// The split vertex of a tetrahedron of the hierarchy (the midpoint of its longest edge), or false
// when that midpoint is not a grid point (a finest-level tetrahedron).
bool tetrahedronSplitVertex(const Tetrahedron& t, GridPoint& splitVertex);

class DiamondMesh {
 public:
  explicit DiamondMesh(const LebGrid& grid);

  const LebGrid& grid() const { return grid_; }
  bool isSplit(const GridPoint& d) const {
    if (!grid_.contains(d)) return false;
    const std::uint64_t i = grid_.linearIndex(d);
    return (split_[i >> 6] >> (i & 63)) & 1u;
  }
  std::size_t splitCount() const { return splitCount_; }

  // Splits d (a grid point other than a root corner), after every parent that is not split yet.
  // Returns the diamonds newly split, parents first (empty when d was split already).
  std::vector<GridPoint> split(const GridPoint& d);
  // Whether d is split and none of its children is.
  bool canMerge(const GridPoint& d) const;
  // Merges d; throws std::logic_error naming d when !canMerge(d).
  void merge(const GridPoint& d);

  // The leaf tetrahedra of the current mesh.
  std::vector<Tetrahedron> leafTetrahedra() const;
  // Visits every leaf tetrahedron with the diamond it belongs to: its split vertex's diamond (which
  // is then a leaf diamond, in the split queue), or for a finest-level tetrahedron (no split
  // vertex) the diamond whose split created it; {-1, -1, -1} only for the root tetrahedra of a
  // grid with k = 0. The order is deterministic (that of leafTetrahedra).
  template <class Fn>
  void forEachLeaf(Fn&& fn) const;

 private:
  LebGrid grid_;
  std::vector<std::uint64_t> split_;  // bit linearIndex(d) set when d is split
  std::size_t splitCount_ = 0;
  void setSplit(const GridPoint& d, bool split);
};

// The two halves of t cut at the midpoint m of its longest edge (first keeps the edge's first
// endpoint).
std::array<Tetrahedron, 2> bisectTetrahedron(const Tetrahedron& t, const GridPoint& m);

template <class Fn>
void DiamondMesh::forEachLeaf(Fn&& fn) const {
  struct Item {
    Tetrahedron t;
    GridPoint creator;
  };
  std::vector<Item> stack;
  for (const Tetrahedron& t : rootTetrahedra(grid_)) stack.push_back({t, {-1, -1, -1}});
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    GridPoint m;
    const bool hasSplitVertex = tetrahedronSplitVertex(item.t, m);
    if (!hasSplitVertex || !isSplit(m)) {
      fn(item.t, hasSplitVertex ? m : item.creator);
      continue;
    }
    for (const Tetrahedron& half : bisectTetrahedron(item.t, m)) stack.push_back({half, m});
  }
}

}  // namespace voxref::ref
