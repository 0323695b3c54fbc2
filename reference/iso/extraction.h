// Isosurface extraction from the leaf tetrahedra of an LEB mesh, reading the field through a
// GridField (uncompressed, or compressed with pages decoded on demand) (Gregorski et al. 2004,
// section 4). Marching tetrahedra and its rule for values equal to the isovalue:
// marching_tetrahedra.h. With bounds, a tetrahedron whose diamond's [min, max] excludes the
// isovalue is skipped without reading its values (that is what keeps most pages undecoded).
// Triangles carry the diamond of their tetrahedron (DiamondMesh::forEachLeaf), as the hierarchical
// index of its split vertex. Single-threaded and deterministic.
#pragma once

#include <cstddef>
#include <cstdint>

#include "reference/iso/diamond_bounds.h"
#include "reference/iso/grid_field.h"
#include "reference/iso/iso_mesh.h"
#include "reference/leb/diamond_mesh.h"
#include "reference/leb/hz_order.h"

namespace voxref::ref {

struct ExtractionStats {
  std::size_t leafTetrahedra = 0;
  std::size_t tetrahedraRead = 0;  // whose four values were read (not skipped by the bounds)
  std::size_t triangles = 0;
};

// bounds may be null (every tetrahedron is read). Throws std::invalid_argument when the field's
// grid is not the mesh's.
IsoMesh extractIsosurface(const DiamondMesh& mesh, GridField& field, const DiamondRanges* bounds, double isovalue,
                          ExtractionStats* stats = nullptr);

}  // namespace voxref::ref
