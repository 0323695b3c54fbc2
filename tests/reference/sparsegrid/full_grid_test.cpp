#include "reference/sparsegrid/full_grid.h"

#include <cmath>

#include <gtest/gtest.h>

#include "reference/common/fields.h"

namespace voxref::ref {
namespace {

TEST(ExtractFullGrid, EqualsDirectInterpolationAtEveryNodeOnDyadicData) {
  // Dyadic data: both the dehierarchization and the direct sum are exact.
  for (bool boundary : {false, true}) {
    const SparseGrid g = SparseGrid::fromField({4, boundary}, analyticField("tent_product"));
    const Volume<double> full = extractFullGrid(g);
    ASSERT_EQ(full.dims(), (Dims3{17, 17, 17}));
    for (int z = 0; z <= 16; ++z)
      for (int y = 0; y <= 16; ++y)
        for (int x = 0; x <= 16; ++x) ASSERT_EQ(full.at(x, y, z), g.value({x / 16.0, y / 16.0, z / 16.0}));
  }
}

TEST(ExtractFullGrid, RefusesGridsOverTheMemoryLimit) {
  const SparseGrid g = SparseGrid::fromField({6, true}, analyticField("zero"));
  EXPECT_THROW(extractFullGrid(g, fullGridBytes(6) - 1), std::length_error);
  EXPECT_EQ(fullGridBytes(12), std::size_t{4097} * 4097 * 4097 * 8);
}

}  // namespace
}  // namespace voxref::ref
