#include "reference/leb/huffman.h"

#include <algorithm>
#include <functional>
#include <queue>
#include <random>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

std::uint64_t cost(const std::vector<std::uint64_t>& counts, const std::vector<std::uint8_t>& lengths) {
  std::uint64_t c = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) c += counts[i] * lengths[i];
  return c;
}

// Huffman's algorithm with a priority queue: the cost of an unrestricted optimal code is the sum
// of the merged weights (an independent derivation of the optimum).
std::uint64_t huffmanCost(const std::vector<std::uint64_t>& counts) {
  std::priority_queue<std::uint64_t, std::vector<std::uint64_t>, std::greater<>> q;
  for (std::uint64_t c : counts)
    if (c) q.push(c);
  if (q.size() == 1) return q.top();
  std::uint64_t total = 0;
  while (q.size() > 1) {
    const std::uint64_t a = q.top();
    q.pop();
    const std::uint64_t b = q.top();
    q.pop();
    total += a + b;
    q.push(a + b);
  }
  return total;
}

// The cheapest length vector with lengths in [1, limit] and Kraft sum <= 1, by exhaustive search.
std::uint64_t bruteForceLimitedCost(const std::vector<std::uint64_t>& counts, int limit) {
  std::vector<std::uint64_t> used;
  for (std::uint64_t c : counts)
    if (c) used.push_back(c);
  std::uint64_t best = ~0ULL;
  std::vector<int> len(used.size(), 1);
  std::function<void(std::size_t, std::uint64_t, std::uint64_t)> rec = [&](std::size_t i, std::uint64_t kraft,
                                                                           std::uint64_t c) {
    if (kraft > (1ULL << limit)) return;
    if (i == used.size()) {
      best = std::min(best, c);
      return;
    }
    for (int l = 1; l <= limit; ++l)
      rec(i + 1, kraft + (1ULL << (limit - l)), c + used[i] * static_cast<std::uint64_t>(l));
  };
  rec(0, 0, 0);
  return best;
}

TEST(Huffman, PackageMergeIsOptimalWhenTheLimitDoesNotBind) {
  std::mt19937_64 rng(1);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::uint64_t> counts(2 + rng() % 16);
    for (auto& c : counts) c = (rng() % 4 == 0) ? 0 : 1 + rng() % (1u << (rng() % 20));
    if (std::count_if(counts.begin(), counts.end(), [](auto c) { return c > 0; }) < 2) continue;
    const auto lengths = huffmanCodeLengths(counts, 30);
    EXPECT_EQ(codeLengthProblem(lengths, 30), "");
    EXPECT_EQ(cost(counts, lengths), huffmanCost(counts));
  }
}

TEST(Huffman, PackageMergeIsOptimalUnderABindingLimit) {
  std::mt19937_64 rng(2);
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<std::uint64_t> counts(3 + rng() % 4);
    // Fibonacci-like weights make deep Huffman trees, so a limit of 3 binds.
    for (std::size_t i = 0; i < counts.size(); ++i)
      counts[i] = 1 + (rng() % 3) + (i < 2 ? 0 : counts[i - 1] + counts[i - 2]);
    const int limit = 3;
    const auto lengths = huffmanCodeLengths(counts, limit);
    EXPECT_EQ(codeLengthProblem(lengths, limit), "");
    EXPECT_EQ(cost(counts, lengths), bruteForceLimitedCost(counts, limit));
  }
  const std::vector<std::uint64_t> nine(9, 1);
  EXPECT_THROW(huffmanCodeLengths(nine, 3), std::invalid_argument);  // 9 symbols need 4 bits
}

TEST(Huffman, OneSymbolGetsOneBitAndUnusedSymbolsNone) {
  const std::vector<std::uint64_t> counts{0, 0, 42, 0};
  EXPECT_EQ(huffmanCodeLengths(counts), (std::vector<std::uint8_t>{0, 0, 1, 0}));
  EXPECT_EQ(huffmanCodeLengths(std::vector<std::uint64_t>(4, 0)), (std::vector<std::uint8_t>(4, 0)));
}

TEST(Huffman, CanonicalCodesOfRfc1951) {
  // RFC 1951 section 3.2.2's example: lengths (3, 3, 3, 3, 3, 2, 4, 4) for A..H.
  const std::vector<std::uint8_t> lengths{3, 3, 3, 3, 3, 2, 4, 4};
  EXPECT_EQ(canonicalCodes(lengths),
            (std::vector<std::uint32_t>{0b010, 0b011, 0b100, 0b101, 0b110, 0b00, 0b1110, 0b1111}));
  const HuffmanDecodeTable t(lengths);
  ASSERT_EQ(t.bits(), 4);
  EXPECT_EQ(t.entry(0b0000), (5 << 4) | 2);  // F = 00
  EXPECT_EQ(t.entry(0b0110), (1 << 4) | 3);  // B = 011
  EXPECT_EQ(t.entry(0b1111), (7 << 4) | 4);  // H = 1111
}

TEST(Huffman, IncompleteCodesLeaveInvalidEntries) {
  const std::vector<std::uint8_t> lengths{1, 0, 2};  // codes 0 and 10; 11 is no code
  const HuffmanDecodeTable t(lengths);
  EXPECT_EQ(t.entry(0b11), 0);
  EXPECT_NE(t.entry(0b10), 0);
}

TEST(Huffman, LengthsThatAreNotAPrefixCodeAreNamed) {
  EXPECT_NE(codeLengthProblem(std::vector<std::uint8_t>{1, 1, 1})
                .find("not those of a prefix-free code (Kraft sum 6144/4096 > 1)"),
            std::string::npos);
  EXPECT_NE(codeLengthProblem(std::vector<std::uint8_t>{13, 1}).find("symbol 0 has a code of 13 bits"),
            std::string::npos);
  EXPECT_EQ(codeLengthProblem(std::vector<std::uint8_t>{1, 2, 2}), "");
}

}  // namespace
}  // namespace voxref::ref
