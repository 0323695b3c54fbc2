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
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "reference/leb/leb_grid.h"

namespace voxref::ref {

struct Tetrahedron {
  std::array<GridPoint, 4> v;
};

// A tetrahedron of the hierarchy as the traversal meets it: its path (below), the split vertex of
// the tetrahedron it is a half of (its creator; {-1, -1, -1} for a root), and its own split
// vertex, the midpoint of its longest edge, when that is a grid point.
struct LeafVisit {
  Tetrahedron t;
  GridPoint creator{-1, -1, -1};
  std::uint64_t path = 0;
  bool hasSplitVertex = false;
  GridPoint splitVertex{-1, -1, -1};
  // The vertex slots (i < j) of t's longest edge (longestEdge(t)), and the slot of creator among
  // t's corners (-1 for a root): carried, so the traversal and its callers find neither again.
  std::pair<int, int> longest{0, 1};
  int creatorSlot = -1;
  // The diamond a leaf belongs to (DiamondMesh::forEachLeaf).
  const GridPoint& diamond() const { return hasSplitVertex ? splitVertex : creator; }
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
  bool isSplit(const GridPoint& d) const { return grid_.contains(d) && isSplitPoint(d); }
  // isSplit for d a point of the grid (the traversal's split vertices and corners), unchecked.
  bool isSplitPoint(const GridPoint& d) const {
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
  void forEachLeaf(Fn&& fn) const {
    forEachLeafVisit([&](const LeafVisit& v) { fn(v.t, v.diamond()); });
  }
  // The same visit with all the traversal knows of a leaf (LeafVisit), its path among it: paths
  // rise in the visiting order, and a path names one tetrahedron of the hierarchy, the same in
  // every mesh that has it.
  template <class Fn>
  void forEachLeafVisit(Fn&& fn) const;
  // The leaves at or below `start`, a tetrahedron of the hierarchy whose parents are split (a
  // leaf of an earlier mesh that is still in this one), in the visiting order: fn(const LeafVisit&).
  template <class Fn>
  void forEachLeafBelow(const LeafVisit& start, Fn&& fn) const;
  // The leaf on `path` (a path of some tetrahedron of this grid): the first tetrahedron along the
  // path from its root that is not split. Throws std::invalid_argument for a path that is not one.
  LeafVisit leafOnPath(std::uint64_t path) const;

 private:
  LebGrid grid_;
  std::vector<std::uint64_t> split_;  // bit linearIndex(d) set when d is split
  std::size_t splitCount_ = 0;
  void setSplit(const GridPoint& d, bool split);
};

// The squared length of the edge between t's corners in slots i and j.
inline long long edgeLength2(const Tetrahedron& t, int i, int j) {
  const GridPoint &a = t.v[static_cast<std::size_t>(i)], &b = t.v[static_cast<std::size_t>(j)];
  const long long dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

// A tetrahedron's six edges as vertex slots (i < j), in this order everywhere they are numbered.
inline constexpr std::array<std::pair<int, int>, 6> kTetrahedronEdges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

// The longest of the candidate edges of t (the first of equal lengths).
template <std::size_t N>
std::pair<int, int> longestOf(const Tetrahedron& t, const std::array<std::pair<int, int>, N>& candidates) {
  std::pair<int, int> e = candidates[0];
  long long best = -1;
  for (const std::pair<int, int>& edge : candidates)
    if (const long long l = edgeLength2(t, edge.first, edge.second); l > best) {
      best = l;
      e = edge;
    }
  return e;
}

// The vertex slots (i < j) of t's longest edge (unique in an LEB tetrahedron: its edges have the
// lengths of a Kuhn simplex, scaled).
inline std::pair<int, int> longestEdge(const Tetrahedron& t) { return longestOf(t, kTetrahedronEdges); }
// The two halves of t cut at the midpoint m of its longest edge (first keeps the edge's first
// endpoint): the definition the traversal's toHalf follows in place (diamond_mesh_test.cpp
// compares them).
std::array<Tetrahedron, 2> bisectTetrahedron(const Tetrahedron& t, const GridPoint& m);

// A tetrahedron's path: which root tetrahedron, then which half at every bisection below it, and
// how many bisections (its depth, in bits 7..0). The traversal takes the roots from a stack (the
// last root first) and, below a split tetrahedron, its second half before its first; so the
// root's rank 5 - root sits in bits 63..61, and the half taken at depth d (1 for the root's
// halves) sets bit 61 - d when it is the first half. A mesh's grid has at most 3k <= 30
// bisections below a root (k <= kMaxIndexedLebK: bits 60..31), so paths of leaves, which are never
// each other's prefixes, compare as the traversal meets them; the depth tells a tetrahedron from
// its second half's descendants.
inline constexpr std::uint64_t kLeafPathDepthMask = 0xff;
inline std::uint64_t rootLeafPath(int root) { return static_cast<std::uint64_t>(5 - root) << 61; }
inline std::uint64_t halfLeafPath(std::uint64_t parent, int half) {
  const std::uint64_t depth = (parent & kLeafPathDepthMask) + 1;
  return ((parent & ~kLeafPathDepthMask) | (half == 0 ? std::uint64_t{1} << (61 - depth) : 0)) | depth;
}

// The midpoint of a and b, whose coordinate sums are even (so halving them is exact).
inline GridPoint evenMidpoint(const GridPoint& a, const GridPoint& b) {
  return {(a[0] + b[0]) >> 1, (a[1] + b[1]) >> 1, (a[2] + b[2]) >> 1};
}

// The longest edge of a half that toHalf made, whose creator (the split vertex it was cut at) is in
// slot creatorSlot: the longest of the three edges between its other corners, the same pair as
// longestEdge(t). An edge at the split vertex is never a half's longest: bisection is defined by
// the geometry alone, and three bisections below a tetrahedron of the hierarchy its descendants
// are its own shape at half the size (three levels per scale, leb_grid.h), so the tetrahedra of
// the first three levels below the roots, with their creators, show every case there is;
// diamond_mesh_test.cpp compares this with longestEdge on every half of a grid of nine levels.
inline std::pair<int, int> longestEdgeOfHalf(const Tetrahedron& t, int creatorSlot) {
  // The edges between the other corners, in kTetrahedronEdges's order (they are never equal).
  static constexpr std::array<std::array<std::pair<int, int>, 3>, 4> kEdgesAvoiding{{
      {{{1, 2}, {1, 3}, {2, 3}}},
      {{{0, 2}, {0, 3}, {2, 3}}},
      {{{0, 1}, {0, 3}, {1, 3}}},
      {{{0, 1}, {0, 2}, {1, 2}}},
  }};
  return longestOf(t, kEdgesAvoiding[static_cast<std::size_t>(creatorSlot)]);
}

// Completes the visit v of v.t whose longest edge is `longest`: its split vertex when the midpoint
// of that edge is a grid point (the edge's coordinate sums are even).
inline void completeVisitWith(LeafVisit& v, std::pair<int, int> longest) {
  v.longest = longest;
  const GridPoint &a = v.t.v[static_cast<std::size_t>(v.longest.first)],
                  &b = v.t.v[static_cast<std::size_t>(v.longest.second)];
  v.hasSplitVertex = ((a[0] + b[0]) & 1) == 0 && ((a[1] + b[1]) & 1) == 0 && ((a[2] + b[2]) & 1) == 0;
  v.splitVertex = v.hasSplitVertex ? evenMidpoint(a, b) : GridPoint{-1, -1, -1};
}
// The same with the longest edge found from the corners.
inline void completeVisit(LeafVisit& v) { completeVisitWith(v, longestEdge(v.t)); }

// The visit of t with the creator found among its corners (-1 when creator[0] < 0 or it is none).
inline LeafVisit visitOf(const Tetrahedron& t, const GridPoint& creator, std::uint64_t path) {
  LeafVisit v{t, creator, path};
  for (int k = 0; k < 4 && creator[0] >= 0; ++k)
    if (t.v[static_cast<std::size_t>(k)] == creator) v.creatorSlot = k;
  completeVisit(v);
  return v;
}

// Makes the visit `v` of a split tetrahedron the visit of its half `half` (0 or 1), as
// bisectTetrahedron cuts it at v.splitVertex: the split vertex takes the slot of the longest
// edge's second endpoint in the first half and of its first endpoint in the second, and becomes
// the creator.
inline void toHalf(LeafVisit& v, int half) {
  const int slot = half == 0 ? v.longest.second : v.longest.first;
  v.t.v[static_cast<std::size_t>(slot)] = v.splitVertex;
  v.creator = v.splitVertex;
  v.creatorSlot = slot;
  v.path = halfLeafPath(v.path, half);
  completeVisitWith(v, longestEdgeOfHalf(v.t, slot));
}

template <class Fn>
void DiamondMesh::forEachLeafBelow(const LeafVisit& start, Fn&& fn) const {
  // Depth first: a split tetrahedron leaves its first half on the stack, so the stack holds at most
  // one tetrahedron per depth below start (3k <= 30).
  std::array<LeafVisit, 3 * kMaxIndexedLebK + 2> stack;
  // The second half of a split one is taken next without a trip through the stack.
  std::size_t size = 0;
  LeafVisit item = start;
  for (;;) {
    if (!item.hasSplitVertex || !isSplitPoint(item.splitVertex)) {
      fn(item);
      if (size == 0) return;
      item = stack[--size];
      continue;
    }
    toHalf(stack[size++] = item, 0);
    toHalf(item, 1);
  }
}

template <class Fn>
void DiamondMesh::forEachLeafVisit(Fn&& fn) const {
  const std::array<Tetrahedron, 6> roots = rootTetrahedra(grid_);
  for (int r = 5; r >= 0; --r)  // the last root first: rootLeafPath's order
    forEachLeafBelow(visitOf(roots[static_cast<std::size_t>(r)], {-1, -1, -1}, rootLeafPath(r)), fn);
}

}  // namespace voxref::ref
