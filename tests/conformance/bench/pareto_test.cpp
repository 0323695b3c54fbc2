#include "conformance/bench/pareto.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

using Front = std::vector<std::size_t>;

TEST(ParetoFront, EmptyInputGivesEmptyFront) { EXPECT_EQ(paretoFront({}), Front{}); }

TEST(ParetoFront, SinglePointIsTheFront) {
  const std::vector<TradeoffPoint> p = {{0.5, 0.1}};
  EXPECT_EQ(paretoFront(p), Front{0});
  const std::vector<std::string> labels = {"rgba8"};
  EXPECT_EQ(frontCostSummary(p, labels, paretoFront(p)), "rgba8 is both the fastest and the most accurate");
}

TEST(ParetoFront, HandMadePointsWithKnownFront) {
  // cost, error: 0 fast and coarse, 3 slow and exact, 1 between; 2 and 4 are dominated.
  const std::vector<TradeoffPoint> p = {{1.0, 0.1}, {2.0, 0.01}, {3.0, 0.05}, {4.0, 0.001}, {5.0, 0.001}};
  EXPECT_EQ(paretoFront(p), (Front{0, 1, 3}));
  const std::vector<std::string> labels = {"a", "b", "c", "d", "e"};
  EXPECT_EQ(frontCostSummary(p, labels, paretoFront(p)), "from a to d: 4x the time for 100x less error");
}

TEST(ParetoFront, OrderedByCostWhateverTheInputOrder) {
  const std::vector<TradeoffPoint> p = {{4.0, 0.0}, {1.0, 0.1}, {9.0, 0.5}, {2.0, 0.01}};
  EXPECT_EQ(paretoFront(p), (Front{1, 3, 0}));
  const std::vector<std::string> labels = {"float", "rgba8", "slow", "rgba16"};
  EXPECT_EQ(frontCostSummary(p, labels, paretoFront(p)), "from rgba8 to float: 4x the time for zero error (from 0.1)");
}

TEST(ParetoFront, IdenticalPointsAreBothOnTheFront) {
  const std::vector<TradeoffPoint> p = {{1.0, 0.1}, {2.0, 0.0}, {1.0, 0.1}};
  EXPECT_EQ(paretoFront(p), (Front{0, 2, 1}));
}

TEST(ParetoFront, TieInOneCoordinateKeepsOnlyTheBetterPoint) {
  // Same cost: the larger error is dominated. Same error: the slower is dominated.
  const std::vector<TradeoffPoint> p = {{1.0, 0.2}, {1.0, 0.1}, {3.0, 0.0}, {2.0, 0.0}};
  EXPECT_EQ(paretoFront(p), (Front{1, 3}));
}

TEST(ParetoFront, OnePointBeatingAllOthersIsTheWholeFront) {
  const std::vector<TradeoffPoint> p = {{2.0, 0.2}, {1.0, 0.0}, {3.0, 0.1}};
  EXPECT_EQ(paretoFront(p), Front{1});
  const std::vector<std::string> labels = {"a", "b", "c"};
  EXPECT_EQ(frontCostSummary(p, labels, paretoFront(p)), "b is both the fastest and the most accurate");
}

TEST(ParetoFront, NanPointsAreNeverOnTheFrontAndDominateNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<TradeoffPoint> p = {{nan, 0.0}, {2.0, 0.1}, {0.5, nan}};
  EXPECT_EQ(paretoFront(p), Front{1});
}

}  // namespace
}  // namespace voxref::conf
