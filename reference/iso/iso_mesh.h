// An extracted isosurface: an indexed triangle mesh in grid coordinates (one unit per voxel,
// sample (i, j, k) of the volume at (i, j, k)), with per-vertex unit normals and, per triangle,
// the diamond it came from (Gregorski et al. 2004, section 4: triangles are generated per leaf
// tetrahedron, and a leaf tetrahedron belongs to the diamond of its split vertex).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/common/same_bytes.h"

namespace voxref::ref {

// A diamond's id: the hierarchical z-order index H of its split vertex (hz_order.h). Fits 32
// bits for grids up to 1025^3 points; kNoDiamond marks "no diamond" in item buffers.
using DiamondId = std::uint32_t;
inline constexpr DiamondId kNoDiamond = 0xffffffffu;

struct IsoMesh {
  std::vector<glm::vec3> positions;        // grid coordinates
  std::vector<glm::vec3> normals;          // unit length (pointing towards lower field values)
  std::vector<std::uint32_t> indices;      // 3 per triangle, counter-clockwise seen from the normal side
  std::vector<DiamondId> triangleDiamond;  // one per triangle

  std::size_t triangleCount() const { return indices.size() / 3; }
};

// The same mesh bit for bit: indices, the triangles' diamonds, positions and normals (compared as
// bits, so -0 and +0 differ and a NaN equals itself).
inline bool identicalMeshes(const IsoMesh& a, const IsoMesh& b) {
  return a.indices == b.indices && a.triangleDiamond == b.triangleDiamond && sameBytes(a.positions, b.positions) &&
         sameBytes(a.normals, b.normals);
}

}  // namespace voxref::ref
