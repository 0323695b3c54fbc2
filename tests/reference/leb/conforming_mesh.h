// Test helper: the crack-free check of an LEB mesh, shared by the diamond-mesh and the
// view-refinement tests.
#pragma once

#include <algorithm>
#include <array>
#include <map>

#include <gtest/gtest.h>

#include "reference/leb/diamond_mesh.h"

namespace voxref::ref::test_support {

using Face = std::array<GridPoint, 3>;

inline long long det6(const Tetrahedron& t) {  // six times the signed volume
  long long m[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[r][c] = t.v[static_cast<std::size_t>(r + 1)][c] - t.v[0][c];
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

inline bool onCubeBoundary(const Face& f, int n) {
  for (int a = 0; a < 3; ++a)
    if ((f[0][a] == 0 && f[1][a] == 0 && f[2][a] == 0) || (f[0][a] == n && f[1][a] == n && f[2][a] == n)) return true;
  return false;
}

// Crack-free: the leaf tetrahedra fill the cube (volumes add up) and every face is shared by two
// of them, or lies on the cube's boundary and belongs to one. A hanging vertex would leave faces
// that appear once inside the cube.
inline void expectConforming(const DiamondMesh& mesh) {
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

}  // namespace voxref::ref::test_support
