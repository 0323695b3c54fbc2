#include "reference/common/crc32.h"

#include <cstdint>
#include <iostream>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "reference/common/crc32_paths.h"

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

// Both ways of computing it (tables, and folding by carry-less multiplication where the CPU has
// it) at every length from 0 to 700 bytes and every offset from a 16-byte boundary, each from the
// start and continuing from a checksum: the folding's four lanes, its one lane and its tail.
TEST(Crc32, TablesAndFoldingAgreeWithTheBitwiseDefinition) {
  std::mt19937 rng(11);
  std::string buffer(720, '\0');
  for (char& ch : buffer) ch = static_cast<char>(rng());
  for (std::size_t offset = 0; offset < 16; ++offset)
    for (std::size_t length = 0; length + offset <= buffer.size() && length <= 700; ++length) {
      const std::string_view piece = std::string_view(buffer).substr(offset, length);
      const std::uint32_t expected = crc32BitByBit(std::string(piece));
      ASSERT_EQ(crc32_detail::slicedUpdate(0, piece), expected) << "offset " << offset << " length " << length;
      ASSERT_EQ(crc32_detail::foldedUpdate(0, piece), expected) << "offset " << offset << " length " << length;
      const std::uint32_t head = crc32BitByBit(buffer.substr(0, offset));
      ASSERT_EQ(crc32_detail::foldedUpdate(head, piece), crc32BitByBit(buffer.substr(0, offset + length)))
          << "continuing at " << offset << " length " << length;
    }
  if (!crc32_detail::foldedAvailable()) std::cout << "note: this CPU has no carry-less multiply; only the tables ran\n";
}

TEST(Crc32, ContinuesOverPieces) {
  const std::string a = "longest-edge ", b = "bisection";
  EXPECT_EQ(crc32Update(crc32(a), b), crc32(a + b));
}

}  // namespace
}  // namespace voxref::ref
