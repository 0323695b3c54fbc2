#include "reference/leb/leb_padding.h"

#include <functional>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "reference/leb/leb_grid.h"

namespace voxref::ref {
namespace {

// The padding points a prediction reaches, by brute force: from every point inside the volume,
// the split edges (leb_grid.h's checked splitEdge) followed through the padding to the corners.
std::set<std::uint64_t> reachedPadding(const LebGrid& g, const Dims3& dims) {
  std::set<std::uint64_t> reached;
  std::vector<GridPoint> stack;
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x) stack.push_back({x, y, z});
  while (!stack.empty()) {
    const GridPoint p = stack.back();
    stack.pop_back();
    if (isRootCorner(g, p)) continue;
    const SplitEdge e = splitEdge(g, p);
    for (const GridPoint& q : {e.a, e.b})
      if (!insideVolume(q, dims) && reached.insert(g.linearIndex(q)).second) stack.push_back(q);
  }
  return reached;
}

// The shell by its definition (every padding point q of scale H with q_a <= X_a + H - 2), over
// every point of the grid; corners count as scale 2^k.
std::set<std::uint64_t> shellByDefinition(const LebGrid& g, const Dims3& dims) {
  std::set<std::uint64_t> shell;
  for (std::uint64_t i = 0; i < g.pointCount(); ++i) {
    const GridPoint q = g.pointAt(i);
    if (insideVolume(q, dims)) continue;
    const int h = 1 << classifyPoint(g, q).scaleLog2;
    if (isRootCorner(g, q) || (q[0] <= dims[0] + h - 2 && q[1] <= dims[1] + h - 2 && q[2] <= dims[2] + h - 2))
      shell.insert(i);
  }
  return shell;
}

const Dims3 kShapes[] = {{1, 1, 1},  {2, 1, 1},  {17, 1, 1},  {1, 9, 1},  {5, 1, 17},   {9, 9, 9},
                         {10, 9, 9}, {33, 2, 3}, {20, 31, 9}, {3, 33, 5}, {17, 17, 16}, {12, 7, 29}};

TEST(LebPadding, EveryPaddingPointAPredictionReachesLiesInTheShell) {
  for (const Dims3& d : kShapes) {
    SCOPED_TRACE(std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]));
    const LebGrid g = lebGridCovering(d);
    const std::set<std::uint64_t> shell = shellByDefinition(g, d);
    for (std::uint64_t q : reachedPadding(g, d)) EXPECT_TRUE(shell.count(q)) << pointText(g.pointAt(q));
    EXPECT_EQ(LebPadding::shellPoints(g, d), shell.size());
  }
}

// Built level by level, the shell holds every point of the definition, each its prediction: the
// same recursion evaluated directly (memoised) from a volume of distinct values.
TEST(LebPadding, LevelByLevelEqualsTheRecursivePrediction) {
  for (const Dims3& d : kShapes) {
    SCOPED_TRACE(std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]));
    const LebGrid g = lebGridCovering(d);
    std::vector<std::int32_t> volume(static_cast<std::size_t>(d[0]) * d[1] * d[2]);
    for (std::size_t i = 0; i < volume.size(); ++i) volume[i] = static_cast<std::int32_t>((i * 37 + 11) % 251);
    const auto inside = [&](std::size_t vi, int) { return volume[vi]; };
    LebPadding padding(g, d, 1);
    for (int level = -1; level < g.levelCount(); ++level) padding.addLevel(level, inside);
    const std::set<std::uint64_t> shell = shellByDefinition(g, d);
    EXPECT_EQ(padding.size(), shell.size());
    std::map<std::uint64_t, std::int32_t> memo;
    std::function<std::int32_t(const GridPoint&)> value = [&](const GridPoint& p) -> std::int32_t {
      if (insideVolume(p, d)) return volume[volumeIndex(p, d)];
      if (isRootCorner(g, p)) return 0;
      const auto it = memo.find(g.linearIndex(p));
      if (it != memo.end()) return it->second;
      const SplitEdge e = splitEdge(g, p);
      return memo[g.linearIndex(p)] = predictMidpoint(value(e.a), value(e.b));
    };
    for (std::uint64_t q : shell) EXPECT_EQ(padding.at(g.pointAt(q))[0], value(g.pointAt(q)));
    for (std::uint64_t i = 0; i < g.pointCount(); ++i)  // every padding point outside the shell is refused
      if (!insideVolume(g.pointAt(i), d) && !shell.count(i)) {
        EXPECT_THROW(padding.at(g.pointAt(i)), std::logic_error) << pointText(g.pointAt(i));
      }
    EXPECT_EQ(padding.allocatedBytes(), LebPadding::tableBytes(g, d));
  }
}

// A shell point of a level not added yet is refused, not read as a value: the levels are added
// coarse to fine, and a prediction reads only coarser points.
TEST(LebPadding, APointOfALevelNotAddedYetIsRefused) {
  const Dims3 d{20, 31, 9};
  const LebGrid g = lebGridCovering(d);
  const auto inside = [](std::size_t, int) { return 7; };
  LebPadding padding(g, d, 1);
  const int added = g.levelCount() / 2;
  for (int level = -1; level <= added; ++level) padding.addLevel(level, inside);
  int refused = 0, read = 0;
  for (std::uint64_t q : shellByDefinition(g, d)) {
    const GridPoint p = g.pointAt(q);
    if (!isRootCorner(g, p) && classifyPoint(g, p).level > added) {
      EXPECT_THROW(padding.at(p), std::logic_error) << pointText(p);
      ++refused;
    } else {
      EXPECT_NO_THROW(padding.at(p)) << pointText(p);
      ++read;
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(read, 0);
  EXPECT_EQ(padding.size(), static_cast<std::size_t>(read));
}

}  // namespace
}  // namespace voxref::ref
