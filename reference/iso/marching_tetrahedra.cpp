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

}  // namespace

IsoMeshBuilder::IsoMeshBuilder(const LebGrid& grid, double isovalue, const GridPoint& clipHi)
    : grid_(grid), iso_(isovalue), clipHi_(clipHi) {}

std::uint32_t IsoMeshBuilder::newVertex(const glm::dvec3& position, const glm::dvec3& normal) {
  positions_.push_back(position);
  normals_.push_back(normal);
  return static_cast<std::uint32_t>(positions_.size() - 1);
}

std::uint32_t IsoMeshBuilder::crossing(const TetCorner& out, const TetCorner& in) {
  const bool atVertex = in.value == iso_;
  const std::uint64_t key = atVertex ? (kVertexKey << 32) | grid_.linearIndex(in.p)
                                     : (grid_.linearIndex(out.p) << 32) | grid_.linearIndex(in.p);
  if (const std::uint32_t* known = edgeVertex_.find(key)) return *known;
  const glm::dvec3 o(out.p[0], out.p[1], out.p[2]), i(in.p[0], in.p[1], in.p[2]);
  glm::dvec3 position, gradient;
  if (atVertex) {
    position = i;
    gradient = in.gradient;
  } else {
    const double t = (iso_ - out.value) / (static_cast<double>(in.value) - out.value);
    position = o + t * (i - o);
    gradient = out.gradient + t * (in.gradient - out.gradient);
  }
  const double len = glm::length(gradient);
  const std::uint32_t v = newVertex(position, len > 0.0 ? -gradient / len : glm::dvec3(0.0));
  edgeVertex_.try_emplace(key, v);
  return v;
}

std::uint32_t IsoMeshBuilder::clipVertex(std::uint32_t a, std::uint32_t b, int axis) {
  if (a > b) std::swap(a, b);  // one direction for both triangles sharing the edge
  const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | b;
  auto& vertices = clipVertex_[static_cast<std::size_t>(axis)];
  if (const std::uint32_t* known = vertices.find(key)) return *known;
  const glm::dvec3 pa = positions_[a], pb = positions_[b];
  const double t = (clipHi_[axis] - pa[axis]) / (pb[axis] - pa[axis]);
  glm::dvec3 p = pa + t * (pb - pa);
  p[axis] = clipHi_[axis];
  const glm::dvec3 n = normals_[a] + t * (normals_[b] - normals_[a]);
  const double len = glm::length(n);
  const std::uint32_t v = newVertex(p, len > 0.0 ? n / len : glm::dvec3(0.0));
  vertices.try_emplace(key, v);
  return v;
}

void IsoMeshBuilder::emit(std::array<std::uint32_t, 3> tri, const glm::dvec3& outward, DiamondId diamond) {
  if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return;
  const glm::dvec3 n = glm::cross(positions_[tri[1]] - positions_[tri[0]], positions_[tri[2]] - positions_[tri[0]]);
  if (glm::dot(n, outward) < 0.0) std::swap(tri[1], tri[2]);
  // Clip against x <= hi, y <= hi, z <= hi where the volume ends before the grid does. Each
  // plane adds at most one vertex to the convex polygon: at most 6.
  std::array<std::uint32_t, 6> poly{tri[0], tri[1], tri[2]};
  std::size_t size = 3;
  for (int axis = 0; axis < 3; ++axis) {
    if (clipHi_[axis] >= grid_.side()) continue;
    std::array<std::uint32_t, 6> next{};
    std::size_t kept = 0;
    for (std::size_t k = 0; k < size; ++k) {
      const std::uint32_t a = poly[k], b = poly[(k + 1) % size];
      const bool inA = positions_[a][axis] <= clipHi_[axis], inB = positions_[b][axis] <= clipHi_[axis];
      if (inA) next[kept++] = a;
      if (inA != inB) next[kept++] = clipVertex(a, b, axis);
    }
    poly = next;
    size = kept;
    if (size < 3) return;
  }
  for (std::size_t k = 1; k + 1 < size; ++k) {
    const std::uint32_t a = poly[0], b = poly[k], c = poly[k + 1];
    if (a == b || b == c || a == c) continue;
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
    mesh_.triangleDiamond.push_back(diamond);
  }
}

void IsoMeshBuilder::addTetrahedron(const std::array<TetCorner, 4>& c, DiamondId diamond) {
  // The corners inside (value >= isovalue) and outside, each in corner order.
  struct Corners {
    std::array<int, 4> at{};
    std::size_t size = 0;
    void push_back(int k) { at[size++] = k; }
    bool empty() const { return size == 0; }
    int operator[](std::size_t i) const { return at[i]; }
    const int* begin() const { return at.data(); }
    const int* end() const { return at.data() + size; }
  } in, out;
  for (int k = 0; k < 4; ++k) (c[static_cast<std::size_t>(k)].value >= iso_ ? in : out).push_back(k);
  if (in.empty() || out.empty()) return;
  glm::dvec3 outward(0.0);
  for (int k : out)
    outward += glm::dvec3(c[static_cast<std::size_t>(k)].p[0], c[static_cast<std::size_t>(k)].p[1],
                          c[static_cast<std::size_t>(k)].p[2]) /
               double(out.size);
  for (int k : in)
    outward -= glm::dvec3(c[static_cast<std::size_t>(k)].p[0], c[static_cast<std::size_t>(k)].p[1],
                          c[static_cast<std::size_t>(k)].p[2]) /
               double(in.size);
  auto x = [&](int o, int i) { return crossing(c[static_cast<std::size_t>(o)], c[static_cast<std::size_t>(i)]); };
  if (in.size == 1) {
    emit({x(out[0], in[0]), x(out[1], in[0]), x(out[2], in[0])}, outward, diamond);
  } else if (in.size == 3) {
    emit({x(out[0], in[0]), x(out[0], in[1]), x(out[0], in[2])}, outward, diamond);
  } else {  // a quad around the tetrahedron: (o0 i0) (o0 i1) (o1 i1) (o1 i0)
    const std::uint32_t q0 = x(out[0], in[0]), q1 = x(out[0], in[1]), q2 = x(out[1], in[1]), q3 = x(out[1], in[0]);
    emit({q0, q1, q2}, outward, diamond);
    emit({q0, q2, q3}, outward, diamond);
  }
}

IsoMesh IsoMeshBuilder::take() {
  // Only the vertices some triangle uses (clipping leaves some unused), in first-use order.
  std::vector<std::uint32_t> remap(positions_.size(), 0xffffffffu);
  std::vector<std::uint32_t> used;
  for (std::uint32_t& v : mesh_.indices) {
    if (remap[v] == 0xffffffffu) {
      remap[v] = static_cast<std::uint32_t>(used.size());
      used.push_back(v);
    }
    v = remap[v];
  }
  // Vertices without a gradient take the area-weighted normal of their triangles.
  std::vector<glm::dvec3> faceSum(used.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t < mesh_.indices.size(); t += 3) {
    const std::uint32_t a = mesh_.indices[t], b = mesh_.indices[t + 1], cc = mesh_.indices[t + 2];
    const glm::dvec3 n =
        glm::cross(positions_[used[b]] - positions_[used[a]], positions_[used[cc]] - positions_[used[a]]);
    for (std::uint32_t v : {a, b, cc}) faceSum[v] += n;
  }
  IsoMesh mesh = std::move(mesh_);
  mesh.positions.resize(used.size());
  mesh.normals.resize(used.size());
  for (std::size_t v = 0; v < used.size(); ++v) {
    mesh.positions[v] = glm::vec3(positions_[used[v]]);
    glm::dvec3 n = normals_[used[v]];
    if (n == glm::dvec3(0.0)) {
      const double len = glm::length(faceSum[v]);
      n = len > 0.0 ? faceSum[v] / len : glm::dvec3(0.0, 0.0, 1.0);
    }
    mesh.normals[v] = glm::vec3(n);
  }
  mesh_ = IsoMesh{};
  positions_.clear();
  normals_.clear();
  edgeVertex_.clear();
  for (auto& m : clipVertex_) m.clear();
  return mesh;
}

}  // namespace voxref::ref
