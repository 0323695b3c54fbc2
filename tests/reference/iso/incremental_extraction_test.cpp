// The incremental extraction against the oracle extractIsosurface, which reads and marches every
// leaf of the mesh anew: after every step of random and view-driven split and merge sequences the
// two meshes are the same bit for bit, with the same statistics.
#include "reference/iso/incremental_extraction.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "reference/iso/view_refinement.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_stream.h"
#include "tests/reference/iso/iso_mesh_checks.h"
#include "tests/reference/iso/iso_test_fields.h"
#include "tests/reference/leb/grid_points.h"

namespace voxref::ref {
namespace {

using test_support::sameMesh;

// Not a grid cube (padding and clipping on every axis), and values in steps of 50 so that many
// grid points equal the isovalue (the rule for vertices at the isovalue, and collapsed triangles).
Volume<std::uint16_t> steppedBalls(const Dims3& dims) {
  return test_support::volumeOf(dims, [](int x, int y, int z) {
    const double a = std::sqrt((x - 5.2) * (x - 5.2) + (y - 6.1) * (y - 6.1) + (z - 4.3) * (z - 4.3));
    const double b = std::sqrt((x - 11.0) * (x - 11.0) + (y - 3.0) * (y - 3.0) + (z - 7.5) * (z - 7.5));
    return 50.0 * std::round((1000.0 - 90.0 * std::min(a, b)) / 50.0);
  });
}

void expectSame(IncrementalExtraction& inc, DiamondMesh& mesh, GridField& field, const DiamondRanges* bounds,
                double iso, const std::string& where) {
  ExtractionStats full, incremental;
  const IsoMesh expected = extractIsosurface(mesh, field, bounds, iso, &full);
  const IsoMesh got = inc.update(mesh, field, &incremental);
  ASSERT_TRUE(sameMesh(expected, got)) << where << ": " << got.triangleCount() << " triangles, expected "
                                       << expected.triangleCount();
  EXPECT_EQ(incremental.leafTetrahedra, full.leafTetrahedra) << where;
  EXPECT_EQ(incremental.tetrahedraRead, full.tetrahedraRead) << where;
  EXPECT_EQ(incremental.triangles, full.triangles) << where;
}

// Random splits (with their parents) and merges of mergeable diamonds, checked after every batch.
void randomSequence(const Volume<std::uint16_t>& v, double iso, bool withBounds, unsigned seed) {
  DenseGridField field = test_support::denseField(v);
  const LebGrid g = field.grid();
  const DiamondBounds bounds = computeDiamondBounds(g, field.values());
  const DiamondRanges* b = withBounds ? &bounds : nullptr;
  DiamondMesh mesh(g);
  IncrementalExtraction inc(g, v.dims(), b, iso);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(0, g.side());
  std::size_t merges = 0;
  for (int step = 0; step < 60; ++step) {
    for (int op = 0; op < 25; ++op) {
      const GridPoint p{coord(rng), coord(rng), coord(rng)};
      if (isRootCorner(g, p)) continue;
      if (mesh.isSplit(p) || rng() % 3 == 0) {
        if (mesh.canMerge(p)) {
          mesh.merge(p);
          ++merges;
        }
      } else {
        mesh.split(p);
      }
    }
    expectSame(inc, mesh, field, b, iso, "step " + std::to_string(step));
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(merges, 50u);
  EXPECT_GT(mesh.splitCount(), 100u);
}

TEST(IncrementalExtraction, EqualsTheFullExtractionAfterRandomSplitsAndMergesWithBounds) {
  randomSequence(steppedBalls({15, 13, 11}), 600.0, true, 1);
}

TEST(IncrementalExtraction, EqualsTheFullExtractionAfterRandomSplitsAndMergesWithoutBounds) {
  randomSequence(steppedBalls({17, 12, 16}), 550.0, false, 2);
}

TEST(IncrementalExtraction, EqualsTheFullExtractionWhenEveryDiamondIsSplitAndMergedAgain) {
  const Volume<std::uint16_t> v = steppedBalls({9, 8, 7});
  DenseGridField field = test_support::denseField(v);
  const LebGrid g = field.grid();
  DiamondMesh mesh = test_support::fullyRefined(g);
  IncrementalExtraction inc(g, v.dims(), nullptr, 700.0);
  expectSame(inc, mesh, field, nullptr, 700.0, "fully split");
  // Merge from the finest diamonds up until none is split.
  while (mesh.splitCount() > 0) {
    for (const GridPoint& p : test_support::gridPoints(g))
      if (mesh.canMerge(p)) mesh.merge(p);
    expectSame(inc, mesh, field, nullptr, 700.0, std::to_string(mesh.splitCount()) + " split");
    if (::testing::Test::HasFatalFailure()) return;
  }
}

// The frame loop's use: a view-driven refinement over an orbit (splits and merges every frame),
// the field read from the compressed stream, and an isovalue change on the way.
TEST(IncrementalExtraction, FollowsAViewDrivenRefinementFromTheCompressedStream) {
  const Volume<std::uint16_t> v = steppedBalls({17, 15, 13});
  DenseGridField dense = test_support::denseField(v);
  const DiamondBounds bounds = computeDiamondBounds(dense.grid(), dense.values());
  LebEncodeOptions options;
  options.pageBits = 8;
  auto stream = std::make_shared<const LebStream>(parseLebStream(encodeLeb(v, 16, options)));
  CompressedGridField compressed(stream, 1u << 20);
  double iso = 600.0;
  ViewRefinement r(bounds, iso);
  IncrementalExtraction inc(dense.grid(), v.dims(), &bounds, iso);
  RefinementBudget budget;
  budget.threshold = 1.0;
  budget.maxSplits = 300;
  std::size_t merges = 0;
  for (int f = 0; f < 16; ++f) {
    if (f == 9) {
      iso = 450.0;
      r.setIsovalue(iso);
      inc.setIsovalue(iso);
    }
    const double angle = 0.7 * f;
    ViewCamera cam;
    cam.target = {8.0, 7.0, 6.0};
    const double distance = f % 4 < 2 ? 12.0 : 60.0;  // near, then far: merges
    cam.eye = cam.target + distance * glm::dvec3(std::cos(angle), 0.4, std::sin(angle));
    const RefinementStats st = r.update(cam, budget);
    merges += st.merges;
    ExtractionStats full, incremental;
    const IsoMesh expected = extractIsosurface(r.mesh(), dense, &bounds, iso, &full);
    const IsoMesh got = inc.update(r.mesh(), compressed, &incremental);
    ASSERT_TRUE(sameMesh(expected, got)) << "frame " << f;
    EXPECT_EQ(incremental.tetrahedraRead, full.tetrahedraRead) << "frame " << f;
    EXPECT_GT(got.triangleCount(), 0u) << "frame " << f;
  }
  EXPECT_GT(merges, 0u);
}

TEST(IncrementalExtraction, AGridWithoutDiamondsIsItsRootTetrahedra) {
  const Volume<std::uint16_t> v =
      test_support::volumeOf({2, 2, 2}, [](int x, int y, int z) { return 100.0 * (x + 2 * y + 3 * z); });
  DenseGridField field = test_support::denseField(v);
  DiamondMesh mesh(field.grid());
  IncrementalExtraction inc(field.grid(), v.dims(), nullptr, 250.0);
  const IsoMesh expected = extractIsosurface(mesh, field, nullptr, 250.0);
  ASSERT_GT(expected.triangleCount(), 0u);
  EXPECT_TRUE(sameMesh(expected, inc.update(mesh, field)));
}

TEST(IncrementalExtraction, RefusesMeshesAndFieldsOfAnotherGridOrVolume) {
  const Volume<std::uint16_t> v = steppedBalls({9, 9, 9});
  DenseGridField field = test_support::denseField(v);
  const LebGrid g = field.grid();
  IncrementalExtraction inc(g, v.dims(), nullptr, 600.0);
  DenseGridField larger = test_support::denseField(steppedBalls({20, 9, 9}));
  DenseGridField smaller = test_support::denseField(steppedBalls({9, 9, 8}));
  EXPECT_THROW(inc.update(DiamondMesh(g), larger), std::invalid_argument);   // another grid
  EXPECT_THROW(inc.update(DiamondMesh(g), smaller), std::invalid_argument);  // another volume
  EXPECT_THROW(inc.update(DiamondMesh(larger.grid()), field), std::invalid_argument);
  EXPECT_THROW(IncrementalExtraction(g, {40, 9, 9}, nullptr, 600.0), std::invalid_argument);
  const DiamondBounds other = computeDiamondBounds(larger.grid(), larger.values());
  EXPECT_THROW(IncrementalExtraction(g, v.dims(), &other, 600.0), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
