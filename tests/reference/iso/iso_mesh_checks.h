// Test helper: structural checks of an extracted isosurface.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <utility>

#include "reference/iso/iso_mesh.h"

namespace voxref::ref::test_support {

// The same mesh bit for bit: indices, diamonds of the triangles, positions and normals.
inline bool sameMesh(const IsoMesh& a, const IsoMesh& b) { return identicalMeshes(a, b); }

// Directed edges without their reverse: 0 for a closed, consistently oriented surface.
inline std::size_t unmatchedDirectedEdges(const IsoMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e)
      ++edges[{m.indices[t + static_cast<std::size_t>(e)], m.indices[t + static_cast<std::size_t>((e + 1) % 3)]}];
  std::size_t unmatched = 0;
  for (const auto& [e, count] : edges) {
    const auto it = edges.find({e.second, e.first});
    const int reverse = it == edges.end() ? 0 : it->second;
    if (count != reverse) unmatched += static_cast<std::size_t>(std::abs(count - reverse));
  }
  return unmatched;
}

inline bool hasRepeatedIndex(const IsoMesh& m) {
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    if (m.indices[t] == m.indices[t + 1] || m.indices[t + 1] == m.indices[t + 2] || m.indices[t] == m.indices[t + 2])
      return true;
  return false;
}

}  // namespace voxref::ref::test_support
