#include <gtest/gtest.h>

#include <cmath>

#include "conformance/framework/report/worst_samples.h"

namespace voxref::conf {
namespace {

TEST(WorstSamples, LargestFirstTiesByIndexNothingForZeroOrNaN) {
  const std::vector<double> scores{0.0, 3.0, std::nan(""), 5.0, 3.0, -1.0, 0.5};
  EXPECT_EQ(largestScores(scores, 3), (std::vector<std::size_t>{3, 1, 4}));
  EXPECT_EQ(largestScores(scores, 10), (std::vector<std::size_t>{3, 1, 4, 6}));
  EXPECT_TRUE(largestScores({0.0, 0.0}, 5).empty());
}

TEST(WorstSamples, InterleavesKindsSkippingRepeats) {
  EXPECT_EQ(interleaveRanked({{7, 8, 9}, {8, 1}, {}}, 4), (std::vector<std::size_t>{7, 8, 1, 9}));
  EXPECT_EQ(interleaveRanked({{7, 8, 9}, {8, 1}}, 2), (std::vector<std::size_t>{7, 8}));
  EXPECT_TRUE(interleaveRanked({{}, {}}, 3).empty());
}

}  // namespace
}  // namespace voxref::conf
