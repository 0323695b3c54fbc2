#include "reference/common/crc32.h"

#include <string>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

TEST(Crc32, CheckValueOfTheCatalogue) {
  // The "check" value of CRC-32/ISO-HDLC in Greg Cook's catalogue of parametrised CRCs.
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
  EXPECT_EQ(crc32(""), 0u);
}

TEST(Crc32, ContinuesOverPieces) {
  const std::string a = "longest-edge ", b = "bisection";
  EXPECT_EQ(crc32Update(crc32(a), b), crc32(a + b));
}

}  // namespace
}  // namespace voxref::ref
