// Length-limited canonical Huffman codes with table-driven decoding (Gregorski et al. 2004,
// section 3.1: "encoding and decoding can be done with direct table lookups").
//
// Lengths come from the package-merge algorithm (Larmore and Hirschberg 1990), which gives the
// optimal prefix code whose lengths do not exceed a limit; with the paper's 9 symbols of 8-bit
// data the limit never binds (a Huffman code of n symbols is at most n - 1 bits long), with the
// 17 symbols of 16-bit data it caps the decoding tables at 2^kMaxCodeLength entries. Codes are
// canonical (DEFLATE, RFC 1951 section 3.2.2): shorter codes first, equal lengths in symbol order,
// so a code is fully described by its lengths. Ties between equal weights are broken by symbol,
// so the lengths are a deterministic function of the counts.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace voxref::ref {

inline constexpr int kMaxCodeLength = 12;

// Optimal code lengths (0 for symbols of count 0) not longer than maxLength. One used symbol gets
// length 1. Throws std::invalid_argument if the used symbols cannot fit (more than 2^maxLength).
std::vector<std::uint8_t> huffmanCodeLengths(std::span<const std::uint64_t> counts, int maxLength = kMaxCodeLength);

// Why these lengths do not describe a prefix code of at most maxLength bits ("" when they do):
// a length above the limit, or a Kraft sum above 1 (then no prefix-free code has these lengths).
std::string codeLengthProblem(std::span<const std::uint8_t> lengths, int maxLength = kMaxCodeLength);

// The canonical codes of valid lengths (codeLengthProblem == ""); code i has lengths[i] bits.
std::vector<std::uint32_t> canonicalCodes(std::span<const std::uint8_t> lengths);

// Decoding by one lookup: peek bits() bits; entry = (symbol << 4) | length, or 0 where no code
// starts with those bits (an incomplete code: such bits are a corrupt stream).
class HuffmanDecodeTable {
 public:
  HuffmanDecodeTable() = default;
  explicit HuffmanDecodeTable(std::span<const std::uint8_t> lengths);  // lengths must be valid
  int bits() const { return bits_; }
  std::uint16_t entry(std::uint32_t peeked) const { return entries_[peeked]; }
  bool empty() const { return bits_ == 0; }

 private:
  int bits_ = 0;
  std::vector<std::uint16_t> entries_;
};

}  // namespace voxref::ref
