#include "reference/iso/extraction.h"

#include <stdexcept>

#include "reference/iso/marching_tetrahedra.h"

namespace voxref::ref {

IsoMesh extractIsosurface(const DiamondMesh& mesh, GridField& field, const DiamondRanges* bounds, double isovalue,
                          ExtractionStats* stats) {
  const LebGrid& grid = mesh.grid();
  if (field.grid().k != grid.k) throw std::invalid_argument("extraction: the field's grid and the mesh's grid differ");
  if (bounds != nullptr && bounds->lebGrid().k != grid.k)
    throw std::invalid_argument("extraction: the bounds' grid and the mesh's grid differ");
  const Dims3& dims = field.volumeDims();
  IsoMeshBuilder builder(grid, isovalue, {dims[0] - 1, dims[1] - 1, dims[2] - 1});
  const HzOrder order(grid);
  ExtractionStats s;
  // A diamond's tetrahedra come one after another: its hierarchical index is found once.
  GridPoint lastDiamond{-1, -1, -1};
  DiamondId lastId = kNoDiamond;
  mesh.forEachLeaf([&](const Tetrahedron& t, const GridPoint& diamond) {
    ++s.leafTetrahedra;
    const bool hasDiamond = diamond[0] >= 0;
    if (bounds != nullptr && hasDiamond && !bounds->mayContain(diamond, isovalue)) return;
    ++s.tetrahedraRead;
    std::array<FieldSample, 4> f;
    int inside = 0;  // corners at or above the isovalue: the builder's test (marching_tetrahedra.h)
    for (std::size_t k = 0; k < 4; ++k) {
      f[k] = field.at(t.v[k]);
      inside += f[k].value >= isovalue ? 1 : 0;
    }
    if (inside == 0 || inside == 4) return;  // no crossing: the builder would add nothing
    std::array<TetCorner, 4> corners;
    for (std::size_t k = 0; k < 4; ++k) corners[k] = {t.v[k], f[k].value, gradientVector(f[k].gradient)};
    if (hasDiamond && diamond != lastDiamond) {
      lastDiamond = diamond;
      lastId = static_cast<DiamondId>(order.index(diamond));
    }
    builder.addTetrahedron(corners, hasDiamond ? lastId : kNoDiamond);
  });
  IsoMesh out = builder.take();
  s.triangles = out.triangleCount();
  if (stats != nullptr) *stats = s;
  return out;
}

}  // namespace voxref::ref
