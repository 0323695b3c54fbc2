// The tiered bounds (a table of the coarser diamonds, the finest computed from the field) against
// the full table of computeDiamondBounds at every diamond of small grids, and the refinement and
// extraction they drive against the full table's.
#include "reference/iso/tiered_bounds.h"

#include <random>

#include <gtest/gtest.h>

#include "reference/iso/extraction.h"
#include "reference/iso/view_refinement.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_stream.h"
#include "tests/reference/iso/iso_mesh_checks.h"
#include "tests/reference/iso/iso_test_fields.h"
#include "tests/reference/leb/grid_points.h"

namespace voxref::ref {
namespace {

// Noise of the given amplitude on a slope: deltas of every size, ties and extremes anywhere.
Volume<std::uint16_t> noisyVolume(const Dims3& dims, int amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  return test_support::volumeOf(dims, [&](int x, int y, int z) {
    return 3.0 * x + 2.0 * y + z + static_cast<double>(rng() % static_cast<unsigned>(amplitude + 1));
  });
}

void expectSameAsTheFullTable(const Volume<std::uint16_t>& v, int threads) {
  DenseGridField field = test_support::denseField(v);
  const LebGrid g = field.grid();
  const DiamondBounds full = computeDiamondBounds(g, field.values());
  const CoarseDiamondBounds coarse = computeCoarseDiamondBounds(g, field.values(), threads);
  const TieredDiamondBounds tiered(coarse, field, 64);  // a small memo: entries are evicted and recomputed
  for (const GridPoint& p : test_support::diamondPoints(g)) {
    const std::uint64_t i = g.linearIndex(p);
    const DiamondRange r = tiered.rangeOf(p);
    ASSERT_EQ(r.min, full.min[i]) << "k " << g.k << " point " << pointText(p);
    ASSERT_EQ(r.max, full.max[i]) << "k " << g.k << " point " << pointText(p);
    ASSERT_EQ(r.error, full.error[i]) << "k " << g.k << " point " << pointText(p);
    ASSERT_EQ(tiered.errorOf(p), full.errorOf(p));
    for (const double iso : {r.min - 0.5, r.min + 0.0, r.max + 0.0, r.max + 0.5})
      ASSERT_EQ(tiered.mayContain(p, iso), full.mayContain(p, iso));
  }
}

TEST(TieredBounds, EqualTheFullTableAtEveryDiamond) {
  // Grid cubes of k = 1..5 (the finest diamonds next to the faces walk the hierarchy, the others
  // use their stencils) and a volume padded into its grid.
  unsigned seed = 1;
  for (int k = 1; k <= 5; ++k) {
    const int n = (1 << k) + 1;
    for (const int amplitude : {0, 3, 1000}) expectSameAsTheFullTable(noisyVolume({n, n, n}, amplitude, seed++), 1);
  }
  expectSameAsTheFullTable(noisyVolume({30, 19, 25}, 40, 99), 2);
  expectSameAsTheFullTable(test_support::ballVolume({20, 11, 17}, 9.0, 5.0, 7.0), 2);
}

TEST(TieredBounds, SameTableForEveryThreadCountAndFrom8BitValues) {
  const Volume<std::uint16_t> v = noisyVolume({33, 33, 33}, 60, 7);  // values below 256
  const DenseGridField field = test_support::denseField(v);
  const CoarseDiamondBounds a = computeCoarseDiamondBounds(field.grid(), field.values(), 1);
  const CoarseDiamondBounds b = computeCoarseDiamondBounds(field.grid(), field.values(), 2);
  std::vector<std::uint8_t> bytes(field.values().begin(), field.values().end());
  const CoarseDiamondBounds c = computeCoarseDiamondBounds(field.grid(), std::span<const std::uint8_t>(bytes), 2);
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
  EXPECT_EQ(a.error, b.error);
  EXPECT_EQ(a.min, c.min);
  EXPECT_EQ(a.max, c.max);
  EXPECT_EQ(a.error, c.error);
  EXPECT_EQ(a.min.size(), 17u * 17u * 17u);  // one point in eight
}

TEST(TieredBounds, RefinementAndExtractionFromTheStreamMakeTheFullTablesMesh) {
  const Volume<std::uint16_t> v = test_support::ballVolume({40, 30, 35}, 20.0, 14.0, 17.0);
  DenseGridField dense = test_support::denseField(v);
  const DiamondBounds full = computeDiamondBounds(dense.grid(), dense.values());
  LebEncodeOptions options;
  options.pageBits = 8;
  auto stream = std::make_shared<const LebStream>(parseLebStream(encodeLeb(v, 16, options)));
  CompressedGridField compressed(stream, 1u << 20);
  const CoarseDiamondBounds coarse = computeCoarseDiamondBounds(dense.grid(), dense.values());
  const TieredDiamondBounds tiered(coarse, compressed);

  RefinementBudget budget;
  budget.threshold = 0.5;
  ViewCamera cam;
  cam.eye = {20.0, 14.0, -60.0};
  cam.target = {20.0, 14.0, 17.0};
  ViewRefinement a(full, 700.0), b(tiered, 700.0);
  const RefinementStats sa = a.update(cam, budget), sb = b.update(cam, budget);
  EXPECT_GT(sa.splits, 100u);
  EXPECT_EQ(sa.splits, sb.splits);
  EXPECT_EQ(sa.splitQueue, sb.splitQueue);
  EXPECT_EQ(a.splitQueue(), b.splitQueue());
  EXPECT_EQ(a.mergeQueue(), b.mergeQueue());
  ExtractionStats ea, eb;
  const IsoMesh ma = extractIsosurface(a.mesh(), dense, &full, 700.0, &ea);
  const IsoMesh mb = extractIsosurface(b.mesh(), compressed, &tiered, 700.0, &eb);
  ASSERT_GT(ma.triangleCount(), 50u);
  EXPECT_TRUE(test_support::sameMesh(ma, mb));
  EXPECT_EQ(ea.tetrahedraRead, eb.tetrahedraRead);
}

TEST(TieredBounds, RefuseValuesOfAnotherSizeAndAFieldOfAnotherGrid) {
  const LebGrid g = makeLebGrid(3);
  const std::vector<std::uint16_t> few(100, 0);
  EXPECT_THROW(computeCoarseDiamondBounds(g, few), std::invalid_argument);
  DenseGridField small = test_support::denseField(test_support::ballVolume({9, 9, 9}, 4.0, 4.0, 4.0));
  const CoarseDiamondBounds other =
      computeCoarseDiamondBounds(makeLebGrid(4), std::vector<std::uint16_t>(17 * 17 * 17, 0));
  EXPECT_THROW(TieredDiamondBounds(other, small), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
