#include "conformance/bench/leb_datasets.h"

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

TEST(RepeatedRowShare, CountsRowsThatRepeatAnEarlierRow) {
  // Rows of 3 bytes: "abc" (new), "abd" (new), "abc" (repeats row 0), "zzz" (one byte repeated:
  // left out), "abd" (repeats row 1), "cba" (new, the mirror of row 0 is not a repeat): 2 of 5.
  EXPECT_DOUBLE_EQ(repeatedRowShare("abcabdabczzzabdcba", 3), 2.0 / 5.0);
}

TEST(RepeatedRowShare, ConstantRowsAreLeftOutAndNoRowGivesZero) {
  EXPECT_DOUBLE_EQ(repeatedRowShare(std::string(12, '\0'), 4), 0.0);
  EXPECT_DOUBLE_EQ(repeatedRowShare("", 4), 0.0);
  EXPECT_DOUBLE_EQ(repeatedRowShare("abab", 2), 1.0 / 2.0);
}

TEST(RepeatedRowShare, RowsThatDoNotDivideTheBytesAreRefused) {
  EXPECT_THROW(repeatedRowShare("abcde", 2), std::invalid_argument);
  EXPECT_THROW(repeatedRowShare("abcd", 0), std::invalid_argument);
}

}  // namespace
}  // namespace voxref::conf
