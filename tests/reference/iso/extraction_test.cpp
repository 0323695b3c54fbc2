// Extraction through the compressed stream equals extraction from the uncompressed grid, bit for
// bit, and decodes only some of the pages; skipping by the bounds changes nothing.
#include "reference/iso/extraction.h"

#include <gtest/gtest.h>

#include "reference/iso/view_refinement.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_stream.h"
#include "tests/reference/iso/iso_mesh_checks.h"
#include "tests/reference/iso/iso_test_fields.h"

namespace voxref::ref {
namespace {

using test_support::sameMesh;

TEST(Extraction, FromTheCompressedStreamEqualsTheUncompressedGridAndDecodesFewerPages) {
  // Not a grid cube, so the padding and the clipping take part.
  const Volume<std::uint16_t> v = test_support::ballVolume({40, 30, 35}, 20.0, 14.0, 17.0);
  DenseGridField dense = test_support::denseField(v);
  const DiamondBounds bounds = computeDiamondBounds(dense.grid(), dense.values());
  LebEncodeOptions options;
  options.pageBits = 8;
  auto stream = std::make_shared<const LebStream>(parseLebStream(encodeLeb(v, 16, options)));
  CompressedGridField compressed(stream, 1u << 20);

  ViewRefinement r(bounds, 700.0);
  RefinementBudget budget;
  budget.threshold = 0.5;
  ViewCamera cam;
  cam.eye = {20.0, 14.0, -60.0};
  cam.target = {20.0, 14.0, 17.0};
  r.update(cam, budget);
  ExtractionStats ds, cs;
  const IsoMesh fromDense = extractIsosurface(r.mesh(), dense, &bounds, 700.0, &ds);
  const IsoMesh fromStream = extractIsosurface(r.mesh(), compressed, &bounds, 700.0, &cs);
  ASSERT_GT(fromDense.triangleCount(), 50u);
  EXPECT_TRUE(sameMesh(fromDense, fromStream));
  EXPECT_EQ(ds.tetrahedraRead, cs.tetrahedraRead);
  EXPECT_LT(ds.tetrahedraRead, ds.leafTetrahedra);
  const std::uint64_t pagesDecoded = compressed.reader().cacheStats().misses;  // a miss decodes the page
  EXPECT_GT(pagesDecoded, 0u);
  EXPECT_LT(pagesDecoded, 2 * stream->pageCount());  // data and gradients channels

  const IsoMesh unbounded = extractIsosurface(r.mesh(), dense, nullptr, 700.0);
  EXPECT_TRUE(sameMesh(fromDense, unbounded));
}

TEST(Extraction, RejectsAFieldOfAnotherGrid) {
  DenseGridField small = test_support::denseField(test_support::ballVolume({9, 9, 9}, 4.0, 4.0, 4.0));
  DiamondMesh mesh(makeLebGrid(4));
  EXPECT_THROW(extractIsosurface(mesh, small, nullptr, 500.0), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
