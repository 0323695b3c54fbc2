#include "conformance/framework/compare.h"

#include <cmath>

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

TEST(CodeDistance, LsbForUnormUlpForFloat) {
  EXPECT_EQ(codeDistance(ref::FramebufferFormat::RGBA8, 3, 7), 4u);
  EXPECT_EQ(codeDistance(ref::FramebufferFormat::RGBA16F, 0x3c00, 0x3c01), 1u);
  EXPECT_EQ(codeDistance(ref::FramebufferFormat::RGBA16F, 0x0001, 0x8001), 2u);  // +2^-24 and -2^-24 across zero
  EXPECT_EQ(codeDistance(ref::FramebufferFormat::RGBA16F, 0x0000, 0x8000), 0u);  // +0 and -0 are one value
  EXPECT_EQ(codeDistance(ref::FramebufferFormat::RGBA32F, 0x3f800000, 0x3f800003), 3u);
}

TEST(CompareCodes, CountsMismatchesAndExclusions) {
  ref::CodePlanes a{ref::FramebufferFormat::RGBA8, 2, 2, 1, {1, 2, 3, 4}};
  ref::CodePlanes b = a;
  b.codes[1] = 9;
  b.codes[3] = 0;
  const std::vector<std::uint8_t> exclude{0, 0, 0, 1};
  const CodeComparison c = compareCodes(a, b, &exclude);
  EXPECT_EQ(c.compared, 3u);
  EXPECT_EQ(c.excluded, 1u);
  EXPECT_EQ(c.mismatched, 1u);
  EXPECT_EQ(c.maxDistance, 7u);
  EXPECT_EQ(c.firstMismatch, 1u);
  EXPECT_EQ(c.mask, (std::vector<std::uint8_t>{0, 1, 0, 0}));
  ref::CodePlanes other = a;
  other.format = ref::FramebufferFormat::RGBA16;
  EXPECT_THROW(compareCodes(a, other), std::invalid_argument);
}

TEST(CompareValues, FiguresFromTheirDefinitions) {
  const ErrorFigures e = compareValues({0.0, 0.5, 1.0, 1.0}, {0.0, 0.5, 0.5, 1.0}, 1.0);
  EXPECT_EQ(e.maxAbs, 0.5);
  EXPECT_EQ(e.argMax, 2u);
  EXPECT_EQ(e.rmse, 0.25);  // sqrt(0.25 / 4)
  EXPECT_NEAR(e.psnrDb, 20 * std::log10(4.0), 1e-12);
  EXPECT_TRUE(std::isinf(compareValues({1.0}, {1.0}, 1.0).psnrDb));
}

}  // namespace
}  // namespace voxref::conf
