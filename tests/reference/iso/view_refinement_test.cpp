// View-dependent refinement: the mesh stays crack-free through every frame of an orbit, the
// queues hold what they must, thresholds and budgets are honoured, occluded diamonds stay coarse.
#include "reference/iso/view_refinement.h"

#include <gtest/gtest.h>

#include "tests/reference/iso/iso_test_fields.h"
#include "tests/reference/leb/conforming_mesh.h"

namespace voxref::ref {
namespace {

struct Scene {
  Volume<std::uint16_t> volume = test_support::ballVolume({33, 33, 33}, 14.2, 17.7, 15.1);
  DenseGridField field = test_support::denseField(volume);
  DiamondBounds bounds = computeDiamondBounds(field.grid(), field.values());
};

ViewCamera cameraAt(int frame) {
  OrbitPath path;
  path.center = {16.0, 16.0, 16.0};
  path.radius = 60.0;
  path.azimuthEndDegrees = 300.0;
  path.frames = 12;
  ViewCamera base;
  base.width = base.height = 64;
  return orbitCamera(path, frame, base);
}

void expectQueuesConsistent(const ViewRefinement& r) {
  const DiamondMesh& mesh = r.mesh();
  for (const GridPoint& d : r.splitQueue()) {
    ASSERT_FALSE(mesh.isSplit(d));
    for (const GridPoint& p : diamondParents(mesh.grid(), d)) ASSERT_TRUE(mesh.isSplit(p));
  }
  for (const GridPoint& d : r.mergeQueue()) ASSERT_TRUE(mesh.canMerge(d));
}

TEST(ViewRefinement, StaysCrackFreeThroughAnOrbitWithSmallBudgets) {
  const Scene s;
  ViewRefinement r(s.bounds, 500.0);
  RefinementBudget budget;
  budget.threshold = 0.5;
  budget.maxSplits = 40;
  budget.maxMerges = 25;
  for (int frame = 0; frame < 12; ++frame) {
    const RefinementStats st = r.update(cameraAt(frame), budget);
    EXPECT_LE(st.splits, budget.maxSplits + static_cast<std::size_t>(s.field.grid().levelCount()));
    EXPECT_LE(st.merges, budget.maxMerges);
    test_support::expectConforming(r.mesh());
    expectQueuesConsistent(r);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(r.mesh().splitCount(), 100u);
}

TEST(ViewRefinement, ConvergesUnderTheThresholdWithoutABudget) {
  const Scene s;
  ViewRefinement r(s.bounds, 500.0);
  RefinementBudget budget;
  budget.threshold = 1.0;
  const RefinementStats first = r.update(cameraAt(0), budget);
  EXPECT_FALSE(first.budgetExhausted);
  for (const GridPoint& d : r.splitQueue()) EXPECT_LE(r.priority(d), budget.threshold);
  for (const GridPoint& d : r.mergeQueue()) EXPECT_GT(r.priority(d), budget.threshold);
  // The same camera again changes nothing.
  const RefinementStats again = r.update(cameraAt(0), budget);
  EXPECT_EQ(again.splits, 0u);
  EXPECT_EQ(again.merges, 0u);
}

TEST(ViewRefinement, DiamondsWithoutTheIsovalueOrOccludedStayCoarse) {
  const Scene s;
  RefinementBudget budget;
  budget.threshold = 0.0;
  ViewRefinement outside(s.bounds, 5000.0);  // above the data
  EXPECT_EQ(outside.update(cameraAt(0), budget).splits, 0u);
  ViewRefinement occluded(s.bounds, 500.0);
  EXPECT_EQ(occluded.update(cameraAt(0), budget, [](const GridPoint&) { return true; }).splits, 0u);
}

TEST(ViewRefinement, IsDeterministic) {
  const Scene s;
  RefinementBudget budget;
  budget.threshold = 0.5;
  budget.maxSplits = 300;
  ViewRefinement a(s.bounds, 500.0), b(s.bounds, 500.0);
  for (int frame = 0; frame < 4; ++frame) {
    a.update(cameraAt(frame), budget);
    b.update(cameraAt(frame), budget);
  }
  EXPECT_EQ(a.splitQueue(), b.splitQueue());
  EXPECT_EQ(a.mergeQueue(), b.mergeQueue());
}

}  // namespace
}  // namespace voxref::ref
