#include "reference/leb/diamond_mesh.h"

#include <stdexcept>
#include <string>

namespace voxref::ref {

std::array<Tetrahedron, 6> rootTetrahedra(const LebGrid& g) {
  const int n = g.side();
  const int perm[6][2] = {{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}};
  std::array<Tetrahedron, 6> tets{};
  for (int i = 0; i < 6; ++i) {
    Tetrahedron& t = tets[static_cast<std::size_t>(i)];
    t.v[0] = {0, 0, 0};
    t.v[1] = t.v[0];
    t.v[1][perm[i][0]] = n;
    t.v[2] = t.v[1];
    t.v[2][perm[i][1]] = n;
    t.v[3] = {n, n, n};
  }
  return tets;
}

bool tetrahedronSplitVertex(const Tetrahedron& t, GridPoint& splitVertex) {
  const LeafVisit v = visitOf(t, {-1, -1, -1}, 0);
  if (v.hasSplitVertex) splitVertex = v.splitVertex;
  return v.hasSplitVertex;
}

DiamondMesh::DiamondMesh(const LebGrid& grid)
    : grid_(makeLebGrid(grid.k)),
      split_((requireIndexedGrid(grid_, "the diamond mesh"), static_cast<std::size_t>((grid_.pointCount() + 63) / 64)),
             0) {}

void DiamondMesh::setSplit(const GridPoint& d, bool split) {
  const std::uint64_t i = grid_.linearIndex(d);
  const std::uint64_t bit = std::uint64_t{1} << (i & 63);
  std::uint64_t& word = split_[static_cast<std::size_t>(i >> 6)];
  if (((word & bit) != 0) == split) return;
  word ^= bit;
  if (split) {
    ++splitCount_;
  } else {
    --splitCount_;
  }
}

std::vector<GridPoint> DiamondMesh::split(const GridPoint& d) {
  std::vector<GridPoint> done;
  if (isSplit(d)) return done;
  for (const GridPoint& parent : diamondParents(grid_, d))  // throws for a corner or an outside point
    for (const GridPoint& q : split(parent)) done.push_back(q);
  setSplit(d, true);
  done.push_back(d);
  return done;
}

bool DiamondMesh::canMerge(const GridPoint& d) const {
  if (!isSplit(d)) return false;
  for (const GridPoint& child : diamondChildren(grid_, d))
    if (isSplit(child)) return false;
  return true;
}

void DiamondMesh::merge(const GridPoint& d) {
  if (!canMerge(d))
    throw std::logic_error("diamond " + pointText(d) +
                           (isSplit(d) ? " has a split child: merge the children first" : " is not split"));
  setSplit(d, false);
}

std::array<Tetrahedron, 2> bisectTetrahedron(const Tetrahedron& t, const GridPoint& m) {
  const auto [i, j] = longestEdge(t);
  Tetrahedron a = t, b = t;
  a.v[static_cast<std::size_t>(j)] = m;  // keeps v[i]
  b.v[static_cast<std::size_t>(i)] = m;  // keeps v[j]
  return {a, b};
}

LeafVisit DiamondMesh::leafOnPath(std::uint64_t path) const {
  const std::uint64_t root = path >> 61, depth = path & kLeafPathDepthMask;
  if (root > 5 || depth > static_cast<std::uint64_t>(grid_.levelCount()) ||
      (path & ~kLeafPathDepthMask & ((std::uint64_t{1} << (61 - depth)) - 1)) != 0)
    throw std::invalid_argument("leafOnPath: " + std::to_string(path) + " is not the path of a tetrahedron");
  const int r = 5 - static_cast<int>(root);
  LeafVisit v = visitOf(rootTetrahedra(grid_)[static_cast<std::size_t>(r)], {-1, -1, -1}, rootLeafPath(r));
  for (std::uint64_t d = 1; d <= depth && v.hasSplitVertex && isSplitPoint(v.splitVertex); ++d)
    toHalf(v, (path >> (61 - d)) & 1 ? 0 : 1);
  return v;
}

std::vector<Tetrahedron> DiamondMesh::leafTetrahedra() const {
  std::vector<Tetrahedron> leaves;
  forEachLeaf([&](const Tetrahedron& t, const GridPoint&) { leaves.push_back(t); });
  return leaves;
}

}  // namespace voxref::ref
