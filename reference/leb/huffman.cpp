#include "reference/leb/huffman.h"

#include <algorithm>
#include <stdexcept>

namespace voxref::ref {
namespace {

// An item of package-merge: a weight and how often each symbol occurs in it.
struct Item {
  std::uint64_t weight = 0;
  std::vector<std::uint16_t> uses;
};

}  // namespace

std::vector<std::uint8_t> huffmanCodeLengths(std::span<const std::uint64_t> counts, int maxLength) {
  const std::size_t n = counts.size();
  std::vector<std::uint8_t> lengths(n, 0);
  std::vector<std::size_t> used;
  for (std::size_t s = 0; s < n; ++s)
    if (counts[s] > 0) used.push_back(s);
  if (used.empty()) return lengths;
  if (used.size() == 1) {
    lengths[used[0]] = 1;
    return lengths;
  }
  if (maxLength < 1 || maxLength > 30 || used.size() > (std::size_t{1} << maxLength))
    throw std::invalid_argument(std::to_string(used.size()) + " symbols do not fit in codes of at most " +
                                std::to_string(maxLength) + " bits");
  // Leaves sorted by weight, ties by symbol (stable sort of the symbol order).
  std::stable_sort(used.begin(), used.end(), [&](std::size_t a, std::size_t b) { return counts[a] < counts[b]; });
  std::vector<Item> leaves;
  for (std::size_t i = 0; i < used.size(); ++i) {
    Item it;
    it.weight = counts[used[i]];
    it.uses.assign(used.size(), 0);
    it.uses[i] = 1;
    leaves.push_back(std::move(it));
  }
  // Coin collector's problem: maxLength - 1 rounds of packaging pairs and merging with the
  // leaves (leaves first on equal weights).
  std::vector<Item> list = leaves;
  for (int round = 1; round < maxLength; ++round) {
    std::vector<Item> packages;
    for (std::size_t i = 0; i + 1 < list.size(); i += 2) {
      Item p;
      p.weight = list[i].weight + list[i + 1].weight;
      p.uses = list[i].uses;
      for (std::size_t s = 0; s < p.uses.size(); ++s)
        p.uses[s] = static_cast<std::uint16_t>(p.uses[s] + list[i + 1].uses[s]);
      packages.push_back(std::move(p));
    }
    std::vector<Item> merged;
    merged.reserve(leaves.size() + packages.size());
    std::size_t a = 0, b = 0;
    while (a < leaves.size() || b < packages.size()) {
      if (b == packages.size() || (a < leaves.size() && leaves[a].weight <= packages[b].weight))
        merged.push_back(leaves[a++]);
      else
        merged.push_back(std::move(packages[b++]));
    }
    list = std::move(merged);
  }
  // The 2n - 2 cheapest items: a symbol's length is the number of them it occurs in.
  for (std::size_t i = 0; i < 2 * used.size() - 2; ++i)
    for (std::size_t s = 0; s < used.size(); ++s)
      lengths[used[s]] = static_cast<std::uint8_t>(lengths[used[s]] + list[i].uses[s]);
  return lengths;
}

std::string codeLengthProblem(std::span<const std::uint8_t> lengths, int maxLength) {
  std::uint64_t kraft = 0;  // in units of 2^-maxLength
  for (std::size_t s = 0; s < lengths.size(); ++s) {
    if (lengths[s] > maxLength)
      return "symbol " + std::to_string(s) + " has a code of " + std::to_string(lengths[s]) + " bits, more than the " +
             std::to_string(maxLength) + " allowed";
    if (lengths[s] > 0) kraft += std::uint64_t{1} << (maxLength - lengths[s]);
  }
  if (kraft > (std::uint64_t{1} << maxLength))
    return "the code lengths are not those of a prefix-free code (Kraft sum " + std::to_string(kraft) + "/" +
           std::to_string(std::uint64_t{1} << maxLength) + " > 1)";
  return "";
}

std::vector<std::uint32_t> canonicalCodes(std::span<const std::uint8_t> lengths) {
  // RFC 1951 section 3.2.2.
  int maxLen = 0;
  for (std::uint8_t l : lengths) maxLen = std::max(maxLen, static_cast<int>(l));
  std::vector<std::uint32_t> perLength(static_cast<std::size_t>(maxLen) + 1, 0),
      next(static_cast<std::size_t>(maxLen) + 2, 0);
  for (std::uint8_t l : lengths)
    if (l) ++perLength[l];
  std::uint32_t code = 0;
  for (int len = 1; len <= maxLen; ++len) {
    code = (code + perLength[static_cast<std::size_t>(len - 1)]) << 1;
    next[static_cast<std::size_t>(len)] = code;
  }
  std::vector<std::uint32_t> codes(lengths.size(), 0);
  for (std::size_t s = 0; s < lengths.size(); ++s)
    if (lengths[s]) codes[s] = next[lengths[s]]++;
  return codes;
}

HuffmanDecodeTable::HuffmanDecodeTable(std::span<const std::uint8_t> lengths) {
  for (std::uint8_t l : lengths) bits_ = std::max(bits_, static_cast<int>(l));
  if (bits_ == 0) return;
  entries_.assign(std::size_t{1} << bits_, 0);
  const std::vector<std::uint32_t> codes = canonicalCodes(lengths);
  for (std::size_t s = 0; s < lengths.size(); ++s) {
    if (!lengths[s]) continue;
    const int free = bits_ - lengths[s];
    const std::uint32_t first = codes[s] << free;
    const auto entry = static_cast<std::uint16_t>((s << 4) | lengths[s]);
    for (std::uint32_t i = 0; i < (1u << free); ++i) entries_[first + i] = entry;
  }
}

}  // namespace voxref::ref
