#include "reference/common/same_bytes.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

// Empty vectors are equal without reading their (possibly null) data: the case that made
// UndefinedBehaviorSanitizer stop the suite when memcmp was called on it.
TEST(SameBytes, EmptyVectorsAreEqualAndDifferFromNonEmptyOnes) {
  EXPECT_TRUE(sameBytes(std::vector<float>{}, std::vector<float>{}));
  EXPECT_FALSE(sameBytes(std::vector<float>{}, std::vector<float>{0.0f}));
  EXPECT_FALSE(sameBytes(std::vector<std::uint8_t>{1, 2}, std::vector<std::uint8_t>{1, 2, 3}));
}

// Floats compare as bits, unlike operator==: -0 differs from +0, and a NaN equals itself.
TEST(SameBytes, ComparesFloatsAsBits) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(sameBytes(std::vector<float>{0.0f}, std::vector<float>{-0.0f}));
  EXPECT_TRUE(sameBytes(std::vector<float>{nan, 1.0f}, std::vector<float>{nan, 1.0f}));
  EXPECT_FALSE(sameBytes(std::vector<float>{1.0f, 2.0f}, std::vector<float>{1.0f, std::nextafter(2.0f, 3.0f)}));
}

}  // namespace
}  // namespace voxref::ref
