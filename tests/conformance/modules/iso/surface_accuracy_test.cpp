#include "conformance/modules/iso/surface_accuracy.h"

#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

fx::RayImage image(std::vector<float> depth) {
  fx::RayImage r;
  r.width = static_cast<int>(depth.size());
  r.height = 1;
  r.depth = std::move(depth);
  return r;
}

constexpr float kMiss = std::numeric_limits<float>::infinity();

TEST(CompareSurfaces, SilhouetteAndDepthByHand) {
  // pixel 0: both hit, 0.5 apart; 1: both miss; 2: only the extracted surface hits; 3: only the
  // exact one; 4: both hit, 0.25 apart.
  const SurfaceError e =
      compareSurfaces(image({2.0f, kMiss, 3.0f, kMiss, 4.0f}), image({2.5f, kMiss, kMiss, 1.0f, 4.25f}));
  EXPECT_EQ(e.pixels, 5u);
  EXPECT_EQ(e.silhouettePixels, 2u);
  EXPECT_EQ(e.bothHit, 2u);
  EXPECT_DOUBLE_EQ(e.maxDepth, 0.5);
  EXPECT_DOUBLE_EQ(e.meanDepth, 0.375);
  EXPECT_DOUBLE_EQ(e.silhouetteShare(), 0.4);
}

TEST(CompareSurfaces, IdenticalImagesHaveNoError) {
  const SurfaceError e = compareSurfaces(image({1.0f, kMiss}), image({1.0f, kMiss}));
  EXPECT_EQ(e.silhouettePixels, 0u);
  EXPECT_EQ(e.maxDepth, 0.0);
}

TEST(CompareSurfaces, SizesMustMatch) {
  EXPECT_THROW(compareSurfaces(image({1.0f}), image({1.0f, 2.0f})), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::conf
