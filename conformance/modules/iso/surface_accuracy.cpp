#include "conformance/modules/iso/surface_accuracy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/iso/view_refinement.h"

namespace voxref::conf {

ThresholdSurface extractAtThreshold(const ref::DiamondRanges& bounds, ref::GridField& field,
                                    const ref::ViewCamera& camera, double isovalue, double thresholdPx) {
  ref::ViewRefinement refinement(bounds, isovalue);
  ref::RefinementBudget budget;
  budget.threshold = thresholdPx;
  refinement.update(camera, budget);
  ThresholdSurface s;
  s.mesh = ref::extractIsosurface(refinement.mesh(), field, &bounds, isovalue, &s.stats);
  s.splitDiamonds = refinement.mesh().splitCount();
  return s;
}

SurfaceError compareSurfaces(const fx::RayImage& extracted, const fx::RayImage& exact) {
  if (extracted.depth.size() != exact.depth.size())
    throw std::invalid_argument("compareSurfaces: images of " + std::to_string(extracted.depth.size()) + " and " +
                                std::to_string(exact.depth.size()) + " pixels");
  SurfaceError e;
  e.pixels = exact.depth.size();
  double sum = 0.0;
  for (std::size_t i = 0; i < exact.depth.size(); ++i) {
    const bool a = std::isfinite(extracted.depth[i]), b = std::isfinite(exact.depth[i]);
    if (a != b) ++e.silhouettePixels;
    if (a && b) {
      const double d = std::fabs(static_cast<double>(extracted.depth[i]) - exact.depth[i]);
      ++e.bothHit;
      sum += d;
      e.maxDepth = std::max(e.maxDepth, d);
    }
  }
  e.meanDepth = e.bothHit ? sum / static_cast<double>(e.bothHit) : 0.0;
  return e;
}

}  // namespace voxref::conf
