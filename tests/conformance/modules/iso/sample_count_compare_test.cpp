#include "conformance/modules/iso/sample_count_compare.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace voxref::conf {
namespace {

TEST(SampleCountCompare, EqualCountsDifferNowhere) {
  const std::vector<std::uint32_t> a = {0, 5, 7};
  const SampleCountComparison c = compareSampleCounts(a, a);
  EXPECT_EQ(c.boxes, 3u);
  EXPECT_EQ(c.differing, 0u);
  EXPECT_EQ(c.verdictsDiffering, 0u);
  EXPECT_TRUE(c.first.empty());
}

TEST(SampleCountCompare, CountsEveryDifferenceAndTheVerdictsThatChange) {
  const std::vector<std::uint32_t> queries = {0, 5, 7, 9, 0}, buffer = {0, 6, 0, 9, 1};
  const SampleCountComparison c = compareSampleCounts(queries, buffer);
  EXPECT_EQ(c.differing, 3u);          // boxes 1, 2 and 4
  EXPECT_EQ(c.verdictsDiffering, 2u);  // boxes 2 and 4: hidden by one count, visible by the other
  EXPECT_EQ(c.first, "box 1: 5 samples by its query, 6 in the buffer");
}

TEST(SampleCountCompare, RefusesCountsOfDifferentBoxes) {
  const std::vector<std::uint32_t> a = {1, 2}, b = {1};
  EXPECT_THROW(compareSampleCounts(a, b), std::invalid_argument);
}

TEST(SampleCountCompare, AccumulatesFramesKeepingTheFirstDifference) {
  SampleCountComparison total;
  const std::vector<std::uint32_t> same = {1, 2}, a = {3}, b = {4}, c = {0}, d = {2};
  accumulate(total, compareSampleCounts(same, same));
  accumulate(total, compareSampleCounts(a, b));
  accumulate(total, compareSampleCounts(c, d));
  EXPECT_EQ(total.boxes, 4u);
  EXPECT_EQ(total.differing, 2u);
  EXPECT_EQ(total.verdictsDiffering, 1u);
  EXPECT_EQ(total.first, "box 0: 3 samples by its query, 4 in the buffer");
}

}  // namespace
}  // namespace voxref::conf
