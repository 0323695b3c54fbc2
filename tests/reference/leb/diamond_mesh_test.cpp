#include "reference/leb/diamond_mesh.h"

#include <algorithm>
#include <map>
#include <random>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

using Face = std::array<GridPoint, 3>;

long long det6(const Tetrahedron& t) {  // six times the signed volume
  long long m[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[r][c] = t.v[static_cast<std::size_t>(r + 1)][c] - t.v[0][c];
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool onCubeBoundary(const Face& f, int n) {
  for (int a = 0; a < 3; ++a)
    if ((f[0][a] == 0 && f[1][a] == 0 && f[2][a] == 0) || (f[0][a] == n && f[1][a] == n && f[2][a] == n)) return true;
  return false;
}

// Crack-free: the leaf tetrahedra fill the cube (volumes add up) and every face is shared by two
// of them, or lies on the cube's boundary and belongs to one. A hanging vertex would leave faces
// that appear once inside the cube.
void expectConforming(const DiamondMesh& mesh) {
  const int n = mesh.grid().side();
  const std::vector<Tetrahedron> leaves = mesh.leafTetrahedra();
  long long volume = 0;
  std::map<Face, int> faces;
  for (const Tetrahedron& t : leaves) {
    const long long d = det6(t);
    ASSERT_NE(d, 0) << "degenerate tetrahedron";
    volume += d < 0 ? -d : d;
    for (int skip = 0; skip < 4; ++skip) {
      Face f;
      int k = 0;
      for (int i = 0; i < 4; ++i)
        if (i != skip) f[static_cast<std::size_t>(k++)] = t.v[static_cast<std::size_t>(i)];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  }
  EXPECT_EQ(volume, 6LL * n * n * n);
  for (const auto& [f, count] : faces) ASSERT_EQ(count, onCubeBoundary(f, n) ? 1 : 2) << "a crack or an overlap";
  // Every diamond split has its split vertex in the mesh; no other grid point is a vertex.
  for (const Tetrahedron& t : leaves)
    for (const GridPoint& v : t.v) ASSERT_TRUE(isRootCorner(mesh.grid(), v) || mesh.isSplit(v));
}

TEST(DiamondMesh, RandomSplitAndMergeSequencesStayConforming) {
  const LebGrid g = makeLebGrid(3);
  std::mt19937 rng(2004);
  std::uniform_int_distribution<int> coord(0, g.side());
  for (int run = 0; run < 20; ++run) {
    DiamondMesh mesh(g);
    expectConforming(mesh);
    EXPECT_EQ(mesh.leafTetrahedra().size(), 6u);
    for (int step = 0; step < 60; ++step) {
      const GridPoint p{coord(rng), coord(rng), coord(rng)};
      if (isRootCorner(g, p)) continue;
      if (rng() % 3 == 0) {
        if (mesh.canMerge(p)) mesh.merge(p);
      } else {
        const auto done = mesh.split(p);
        for (const GridPoint& d : done)
          for (const GridPoint& parent : diamondParents(g, d)) ASSERT_TRUE(mesh.isSplit(parent));
      }
      expectConforming(mesh);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}

TEST(DiamondMesh, FullRefinementHasSixTetrahedraPerCell) {
  const LebGrid g = makeLebGrid(2);
  DiamondMesh mesh(g);
  for (int z = 0; z <= 4; ++z)
    for (int y = 0; y <= 4; ++y)
      for (int x = 0; x <= 4; ++x)
        if (!isRootCorner(g, {x, y, z})) mesh.split({x, y, z});
  EXPECT_EQ(mesh.splitCount(), g.pointCount() - 8);
  EXPECT_EQ(mesh.leafTetrahedra().size(), 6u * 64u);
  expectConforming(mesh);
}

TEST(DiamondMesh, MergeRefusesASplitChildAndSplitBringsParents) {
  const LebGrid g = makeLebGrid(2);
  DiamondMesh mesh(g);
  const auto done = mesh.split({1, 1, 1});  // a level-3 cube centre: needs levels 0, 1, 2 first
  EXPECT_GT(done.size(), 1u);
  EXPECT_EQ(done.front(), (GridPoint{2, 2, 2}));
  EXPECT_EQ(done.back(), (GridPoint{1, 1, 1}));
  EXPECT_FALSE(mesh.canMerge({2, 2, 2}));
  EXPECT_THROW(mesh.merge({2, 2, 2}), std::logic_error);
  EXPECT_TRUE(mesh.canMerge({1, 1, 1}));
  mesh.merge({1, 1, 1});
  EXPECT_FALSE(mesh.isSplit({1, 1, 1}));
  EXPECT_THROW(mesh.split({0, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
