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
// one plane per axis where hi is below the grid's side), new vertices keyed by the clipped edge,
// so clipped triangles stay connected.
#pragma once

#include <array>
#include <cstdint>

#include "reference/common/flat_u64_map.h"
#include "reference/iso/iso_mesh.h"
#include "reference/leb/leb_grid.h"

namespace voxref::ref {

struct TetCorner {
  GridPoint p;
  std::uint16_t value;
  glm::dvec3 gradient;
};

class IsoMeshBuilder {
 public:
  // clipHi: the largest coordinate kept per axis (the volume's extent - 1).
  IsoMeshBuilder(const LebGrid& grid, double isovalue, const GridPoint& clipHi);

  void addTetrahedron(const std::array<TetCorner, 4>& corners, DiamondId diamond);
  // The mesh; the builder is empty afterwards.
  IsoMesh take();

 private:
  std::uint32_t crossing(const TetCorner& out, const TetCorner& in);
  std::uint32_t clipVertex(std::uint32_t a, std::uint32_t b, int axis);
  void emit(std::array<std::uint32_t, 3> tri, const glm::dvec3& outward, DiamondId diamond);
  std::uint32_t newVertex(const glm::dvec3& position, const glm::dvec3& normal);

  LebGrid grid_;
  double iso_;
  GridPoint clipHi_;
  IsoMesh mesh_;
  std::vector<glm::dvec3> positions_, normals_;          // double while building
  FlatU64Map<std::uint32_t> edgeVertex_;                 // (outside, inside) linear indices
  std::array<FlatU64Map<std::uint32_t>, 3> clipVertex_;  // per axis: (vertex, vertex)
};

}  // namespace voxref::ref
