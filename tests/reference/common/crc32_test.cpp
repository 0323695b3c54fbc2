#include "reference/common/crc32.h"

#include <cstdint>
#include <random>
#include <string>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

TEST(Crc32, CheckValueOfTheCatalogue) {
  // The "check" value of CRC-32/ISO-HDLC in Greg Cook's catalogue of parametrised CRCs.
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
  EXPECT_EQ(crc32(""), 0u);
}

TEST(Crc32, KnownValueOfALongerText) {
  // More than eight bytes: the eight-byte steps, then the byte-wise tail.
  EXPECT_EQ(crc32("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
}

// The definition bit by bit (reflected polynomial division), independent of the tables.
std::uint32_t crc32BitByBit(const std::string& bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (const char ch : bytes) {
    c ^= static_cast<unsigned char>(ch);
    for (int b = 0; b < 8; ++b) c = (c >> 1) ^ ((c & 1u) ? 0xEDB88320u : 0u);
  }
  return ~c;
}

TEST(Crc32, AgreesWithTheBitwiseDefinitionAtEveryLengthAndAlignment) {
  std::mt19937 rng(7);
  std::string buffer(300, '\0');
  for (char& ch : buffer) ch = static_cast<char>(rng());
  for (std::size_t offset = 0; offset < 9; ++offset)
    for (std::size_t length = 0; length + offset <= buffer.size(); length += 7) {
      const std::string piece = buffer.substr(offset, length);
      ASSERT_EQ(crc32(std::string_view(buffer).substr(offset, length)), crc32BitByBit(piece))
          << "offset " << offset << " length " << length;
    }
}

TEST(Crc32, ContinuesOverPieces) {
  const std::string a = "longest-edge ", b = "bisection";
  EXPECT_EQ(crc32Update(crc32(a), b), crc32(a + b));
}

}  // namespace
}  // namespace voxref::ref
