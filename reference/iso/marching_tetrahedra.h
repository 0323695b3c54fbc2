// Marching tetrahedra on the leaf tetrahedra of an LEB mesh (Gregorski et al. 2004, section 4:
// "the isosurface is extracted from the leaf tetrahedra"), building one indexed, watertight mesh.
//
// The rule for values equal to the isovalue (one rule, everywhere): a vertex is INSIDE when its
// value is >= the isovalue. The surface crosses an edge (o, i) with o outside and i inside at
//     x = o + t (i - o),  t = (iso - f(o)) / (f(i) - f(o)) in (0, 1],
// computed in double from o to i, so both tetrahedra sharing the edge compute the same point.
// When t = 1 (f(i) = iso) the point is the grid vertex i itself, and every edge ending at i
// shares that one mesh vertex. Triangles whose indices repeat (collapsed on such a vertex) are
// dropped. Hence: a face of the leaf mesh yields the same segment (or none) from both of its
// tetrahedra, and where the surface does not reach the clip box it is closed: every directed
// edge of the mesh has its reverse (the test walks them). Flat regions at the isovalue are
// inside and produce no triangles; the surface runs where they meet values below it.
// Orientation: counter-clockwise seen from outside (the side of lower values), normals
// -gradient interpolated like the position, normalized (the area-weighted face normal where the
// gradient is zero).
//
// Clipping: triangles are clipped to the box [0, hi] (the volume's extent; Sutherland-Hodgman,
// one plane per axis where hi is below the grid's side), new vertices keyed by the clipped edge
// and computed from its endpoint inside the box towards the one outside, so clipped triangles stay
// connected and a clipped vertex does not depend on the order the vertices were made in.
//
// One rule, two vertex stores: marchTetrahedron is the whole rule for one tetrahedron against a
// store that finds or makes the vertices (the builder below, which numbers them per extraction,
// and the persistent store of incremental_extraction.h); assembleIsoMesh turns the triangles into
// the mesh. Both extractions therefore give the same mesh, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "reference/common/flat_u64_map.h"
#include "reference/iso/iso_mesh.h"
#include "reference/leb/leb_grid.h"

namespace voxref::ref {

struct TetCorner {
  GridPoint p;
  std::uint16_t value;
  glm::dvec3 gradient;
};

// A mesh vertex while building: position and normal in double (the normal unit length, or zero
// where the gradient is zero: assembleIsoMesh then takes the area-weighted face normal).
struct MeshVertex {
  glm::dvec3 position, normal;
};
// The vertex where the surface crosses the edge from corner `out` (value below the isovalue) to
// corner `in` (at or above it), and its key: the pair of the corners' linear indices, or the
// grid vertex `in` alone when its value equals the isovalue (the rule above). Linear indices are
// below 2^31 for grids up to 1025^3 points, so a key never equals FlatU64Map's reserved key.
MeshVertex crossingVertex(const TetCorner& out, const TetCorner& in, double isovalue);
std::uint64_t crossingKey(const LebGrid& grid, const TetCorner& out, const TetCorner& in, double isovalue);
// The vertex where the edge from `inside` (coordinate `axis` at most hi) to `outside` (above hi)
// meets the plane x_axis = hi.
MeshVertex clippedVertex(const MeshVertex& inside, const MeshVertex& outside, int axis, double hi);

// The triangles of one tetrahedron under the rule above, against a vertex store:
//   std::uint32_t store.crossing(const TetCorner& out, const TetCorner& in)  the crossing vertex
//   std::uint32_t store.clipVertex(std::uint32_t a, std::uint32_t b, int axis) the clipped edge's
//                                                                                vertex (a, b unordered)
//   const glm::dvec3& store.position(std::uint32_t v)
// Equal vertex numbers mean the same vertex. emit({a, b, c}) receives each triangle, counter-
// clockwise seen from outside, in a fixed order; triangles with a repeated vertex are not emitted.
template <class Store, class Emit>
void marchTetrahedron(const std::array<TetCorner, 4>& corners, double isovalue, const GridPoint& clipHi, int gridSide,
                      Store& store, Emit&& emit);

// The mesh of `indices` (three store vertices per triangle) and their diamonds: the vertices some
// triangle uses, numbered in the order of first use, in float; a vertex without a gradient takes
// the area-weighted normal of its triangles (summed in triangle order), or +z when they have no
// area. positions and normals are indexed by store vertex. scratch, if given, lends its memory
// to the next call (a caller that assembles every frame).
struct AssemblyScratch {
  std::vector<std::uint32_t> remap, used;
  std::vector<std::uint8_t> faceNormal;  // per used vertex: it has no gradient
  std::vector<glm::dvec3> faceSum;
};
IsoMesh assembleIsoMesh(std::vector<std::uint32_t> indices, std::vector<DiamondId> diamonds,
                        std::span<const glm::dvec3> positions, std::span<const glm::dvec3> normals,
                        AssemblyScratch* scratch = nullptr);

class IsoMeshBuilder {
 public:
  // clipHi: the largest coordinate kept per axis (the volume's extent - 1).
  IsoMeshBuilder(const LebGrid& grid, double isovalue, const GridPoint& clipHi);

  void addTetrahedron(const std::array<TetCorner, 4>& corners, DiamondId diamond);
  // The mesh; the builder is empty afterwards.
  IsoMesh take();

 private:
  // marchTetrahedron's store: vertices numbered in the order they are made, for this extraction.
  struct Store;
  std::uint32_t newVertex(const MeshVertex& v);

  LebGrid grid_;
  double iso_;
  GridPoint clipHi_;
  std::vector<std::uint32_t> indices_;
  std::vector<DiamondId> diamonds_;
  std::vector<glm::dvec3> positions_, normals_;          // double while building
  FlatU64Map<std::uint32_t> edgeVertex_;                 // crossingKey
  std::array<FlatU64Map<std::uint32_t>, 3> clipVertex_;  // per axis: (vertex, vertex)
};

template <class Store, class Emit>
void marchTetrahedron(const std::array<TetCorner, 4>& c, double isovalue, const GridPoint& clipHi, int gridSide,
                      Store& store, Emit&& emit) {
  // The corners inside (value >= isovalue) and outside, each in corner order.
  std::array<int, 4> in{}, out{};
  std::size_t ins = 0, outs = 0;
  for (int k = 0; k < 4; ++k) {
    if (c[static_cast<std::size_t>(k)].value >= isovalue) {
      in[ins++] = k;
    } else {
      out[outs++] = k;
    }
  }
  if (ins == 0 || outs == 0) return;
  auto point = [&](int k) {
    const GridPoint& p = c[static_cast<std::size_t>(k)].p;
    return glm::dvec3(p[0], p[1], p[2]);
  };
  glm::dvec3 outward(0.0);
  for (std::size_t k = 0; k < outs; ++k) outward += point(out[k]) / double(outs);
  for (std::size_t k = 0; k < ins; ++k) outward -= point(in[k]) / double(ins);
  auto x = [&](int o, int i) { return store.crossing(c[static_cast<std::size_t>(o)], c[static_cast<std::size_t>(i)]); };
  auto triangle = [&](std::array<std::uint32_t, 3> tri) {
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return;
    const glm::dvec3 p0 = store.position(tri[0]), p1 = store.position(tri[1]), p2 = store.position(tri[2]);
    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    if (glm::dot(n, outward) < 0.0) std::swap(tri[1], tri[2]);
    // Clip against x <= hi, y <= hi, z <= hi where the volume ends before the grid does. Each
    // plane adds at most one vertex to the convex polygon: at most 6. A plane with every corner of
    // the triangle on its inner side keeps the triangle as it is, so until a plane has been walked
    // such planes are not.
    const glm::dvec3 highest = glm::max(p0, glm::max(p1, p2));
    std::array<std::uint32_t, 6> poly{tri[0], tri[1], tri[2]};
    std::size_t size = 3;
    bool walked = false;
    for (int axis = 0; axis < 3; ++axis) {
      if (clipHi[axis] >= gridSide || (!walked && highest[axis] <= clipHi[axis])) continue;
      walked = true;
      std::array<std::uint32_t, 6> next{};
      std::size_t kept = 0;
      for (std::size_t k = 0; k < size; ++k) {
        const std::uint32_t a = poly[k], b = poly[(k + 1) % size];
        const bool inA = store.position(a)[axis] <= clipHi[axis], inB = store.position(b)[axis] <= clipHi[axis];
        if (inA) next[kept++] = a;
        if (inA != inB) next[kept++] = store.clipVertex(a, b, axis);
      }
      poly = next;
      size = kept;
      if (size < 3) return;
    }
    for (std::size_t k = 1; k + 1 < size; ++k) {
      const std::uint32_t a = poly[0], b = poly[k], d = poly[k + 1];
      if (a == b || b == d || a == d) continue;
      emit(std::array<std::uint32_t, 3>{a, b, d});
    }
  };
  if (ins == 1) {
    triangle({x(out[0], in[0]), x(out[1], in[0]), x(out[2], in[0])});
  } else if (ins == 3) {
    triangle({x(out[0], in[0]), x(out[0], in[1]), x(out[0], in[2])});
  } else {  // a quad around the tetrahedron: (o0 i0) (o0 i1) (o1 i1) (o1 i0)
    const std::uint32_t q0 = x(out[0], in[0]), q1 = x(out[0], in[1]), q2 = x(out[1], in[1]), q3 = x(out[1], in[0]);
    triangle({q0, q1, q2});
    triangle({q0, q2, q3});
  }
}

}  // namespace voxref::ref
