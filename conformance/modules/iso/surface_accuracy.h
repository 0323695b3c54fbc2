// What the paper's view-dependent isosurface gives up for speed: the surface extracted at an error
// threshold (Gregorski et al. 2004, section 4: refinement until every diamond's projected error
// is under the threshold in pixels, then marching tetrahedra over the leaves) against the exact
// isosurface of the trilinear field (fixtures/raycast/trilinear_isosurface.h). Used by the
// iso.accuracy.* cases and by the bench's study.iso; one definition of each figure for both.
#pragma once

#include <cstddef>

#include "fixtures/raycast/ray_image.h"
#include "reference/common/view_camera.h"
#include "reference/iso/diamond_bounds.h"
#include "reference/iso/extraction.h"
#include "reference/iso/grid_field.h"
#include "reference/iso/iso_mesh.h"

namespace voxref::conf {

struct ThresholdSurface {
  ref::IsoMesh mesh;
  ref::ExtractionStats stats;
  std::size_t splitDiamonds = 0;
};

// Refines the diamond mesh from the root for `camera` until every diamond whose range holds the
// isovalue projects an error under `thresholdPx` pixels (no split budget beyond the refinement's
// default), then extracts the isosurface of its leaves from `field`. Throws what the reference
// layers throw.
ThresholdSurface extractAtThreshold(const ref::DiamondRanges& bounds, ref::GridField& field,
                                    const ref::ViewCamera& camera, double isovalue, double thresholdPx);

// A ray-cast image of an extracted surface against the exact one, same camera and size:
// silhouette pixels (hit in one image, miss in the other), and over pixels hit in both the mean
// and max absolute eye-depth difference (grid units). A pure function; throws
// std::invalid_argument when the sizes differ.
struct SurfaceError {
  std::size_t pixels = 0, silhouettePixels = 0, bothHit = 0;
  double meanDepth = 0.0, maxDepth = 0.0;
  double silhouetteShare() const {
    return pixels ? static_cast<double>(silhouettePixels) / static_cast<double>(pixels) : 0.0;
  }
};
SurfaceError compareSurfaces(const fx::RayImage& extracted, const fx::RayImage& exact);

}  // namespace voxref::conf
