#include "reference/iso/marching_tetrahedra.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

namespace voxref::ref {
namespace {

// Keys: linear indices are below 2^31 for grids up to 1025^3 points; a vertex-at-grid-point key
// uses the reserved value kVertexKey in the high half.
constexpr std::uint64_t kVertexKey = 0xffffffffULL;

glm::dvec3 unitOrZero(const glm::dvec3& v) {
  const double len = glm::length(v);
  return len > 0.0 ? v / len : glm::dvec3(0.0);
}

}  // namespace

MeshVertex crossingVertex(const TetCorner& out, const TetCorner& in, double isovalue) {
  const glm::dvec3 o(out.p[0], out.p[1], out.p[2]), i(in.p[0], in.p[1], in.p[2]);
  // The normal points towards lower values: minus the unit gradient.
  if (in.value == isovalue) return {i, unitOrZero(-in.gradient)};
  const double t = (isovalue - out.value) / (static_cast<double>(in.value) - out.value);
  return {o + t * (i - o), unitOrZero(-(out.gradient + t * (in.gradient - out.gradient)))};
}

std::uint64_t crossingKey(const LebGrid& grid, const TetCorner& out, const TetCorner& in, double isovalue) {
  return in.value == isovalue ? (kVertexKey << 32) | grid.linearIndex(in.p)
                              : (grid.linearIndex(out.p) << 32) | grid.linearIndex(in.p);
}

MeshVertex clippedVertex(const MeshVertex& inside, const MeshVertex& outside, int axis, double hi) {
  const glm::dvec3 &pa = inside.position, &pb = outside.position;
  const double t = (hi - pa[axis]) / (pb[axis] - pa[axis]);
  glm::dvec3 p = pa + t * (pb - pa);
  p[axis] = hi;
  return {p, unitOrZero(inside.normal + t * (outside.normal - inside.normal))};
}

IsoMesh assembleIsoMesh(std::vector<std::uint32_t> indices, std::vector<DiamondId> diamonds,
                        std::span<const glm::dvec3> positions, std::span<const glm::dvec3> normals,
                        AssemblyScratch* scratch) {
  AssemblyScratch own;
  AssemblyScratch& s = scratch != nullptr ? *scratch : own;
  // Only the vertices some triangle uses (clipping leaves some unused), in first-use order.
  std::vector<std::uint32_t>& remap = s.remap;
  std::vector<std::uint32_t>& used = s.used;
  remap.assign(positions.size(), 0xffffffffu);
  used.clear();
  for (std::uint32_t& v : indices) {
    if (remap[v] == 0xffffffffu) {
      remap[v] = static_cast<std::uint32_t>(used.size());
      used.push_back(v);
    }
    v = remap[v];
  }
  // Vertices without a gradient take the area-weighted normal of their triangles (summed only for
  // them, and only the triangles that touch one: most vertices have a gradient).
  std::vector<std::uint8_t>& faceNormal = s.faceNormal;
  faceNormal.assign(used.size(), 0);
  bool anyFaceNormal = false;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (normals[used[v]] == glm::dvec3(0.0)) {
      faceNormal[v] = 1;
      anyFaceNormal = true;
    }
  std::vector<glm::dvec3>& faceSum = s.faceSum;
  faceSum.assign(anyFaceNormal ? used.size() : 0, glm::dvec3(0.0));
  for (std::size_t t = 0; anyFaceNormal && t < indices.size(); t += 3) {
    const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    if ((faceNormal[a] | faceNormal[b] | faceNormal[c]) == 0) continue;
    const glm::dvec3 n = glm::cross(positions[used[b]] - positions[used[a]], positions[used[c]] - positions[used[a]]);
    for (std::uint32_t v : {a, b, c})
      if (faceNormal[v]) faceSum[v] += n;
  }
  IsoMesh mesh;
  mesh.indices = std::move(indices);
  mesh.triangleDiamond = std::move(diamonds);
  mesh.positions.resize(used.size());
  mesh.normals.resize(used.size());
  for (std::size_t v = 0; v < used.size(); ++v) {
    mesh.positions[v] = glm::vec3(positions[used[v]]);
    glm::dvec3 n = normals[used[v]];
    if (faceNormal[v]) {
      const double len = glm::length(faceSum[v]);
      n = len > 0.0 ? faceSum[v] / len : glm::dvec3(0.0, 0.0, 1.0);
    }
    mesh.normals[v] = glm::vec3(n);
  }
  return mesh;
}

struct IsoMeshBuilder::Store {
  IsoMeshBuilder& b;
  std::uint32_t crossing(const TetCorner& out, const TetCorner& in) {
    const std::uint64_t key = crossingKey(b.grid_, out, in, b.iso_);
    if (const std::uint32_t* known = b.edgeVertex_.find(key)) return *known;
    const std::uint32_t v = b.newVertex(crossingVertex(out, in, b.iso_));
    b.edgeVertex_.try_emplace(key, v);
    return v;
  }
  std::uint32_t clipVertex(std::uint32_t a, std::uint32_t c, int axis) {
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, c)) << 32) | std::max(a, c);
    auto& vertices = b.clipVertex_[static_cast<std::size_t>(axis)];
    if (const std::uint32_t* known = vertices.find(key)) return *known;
    const MeshVertex va{b.positions_[a], b.normals_[a]}, vc{b.positions_[c], b.normals_[c]};
    const double hi = b.clipHi_[axis];
    const std::uint32_t v =
        b.newVertex(va.position[axis] <= hi ? clippedVertex(va, vc, axis, hi) : clippedVertex(vc, va, axis, hi));
    vertices.try_emplace(key, v);
    return v;
  }
  const glm::dvec3& position(std::uint32_t v) const { return b.positions_[v]; }
};

IsoMeshBuilder::IsoMeshBuilder(const LebGrid& grid, double isovalue, const GridPoint& clipHi)
    : grid_(grid), iso_(isovalue), clipHi_(clipHi) {}

std::uint32_t IsoMeshBuilder::newVertex(const MeshVertex& v) {
  positions_.push_back(v.position);
  normals_.push_back(v.normal);
  return static_cast<std::uint32_t>(positions_.size() - 1);
}

void IsoMeshBuilder::addTetrahedron(const std::array<TetCorner, 4>& corners, DiamondId diamond) {
  Store store{*this};
  marchTetrahedron(corners, iso_, clipHi_, grid_.side(), store, [&](const std::array<std::uint32_t, 3>& tri) {
    indices_.insert(indices_.end(), tri.begin(), tri.end());
    diamonds_.push_back(diamond);
  });
}

IsoMesh IsoMeshBuilder::take() {
  IsoMesh mesh = assembleIsoMesh(std::move(indices_), std::move(diamonds_), positions_, normals_);
  indices_.clear();
  diamonds_.clear();
  positions_.clear();
  normals_.clear();
  edgeVertex_.clear();
  for (auto& m : clipVertex_) m.clear();
  return mesh;
}

}  // namespace voxref::ref
