// The vectors a gradient page has coded so far, most recent first (FORMAT.md beside this file,
// "Context gradient pages", step 2): a move-to-front list in which a vector's rank is the number of
// distinct vectors used since its own last use. The context coder codes a vector that repeats one
// of the page's by its rank, which is what lets it catch the exact repeats of a few vectors that
// central differences of 8-bit samples make (zstd's lead on them).
//
// Each vector keeps the time of its last use; a Fenwick tree over the times (Fenwick 1994) counts
// the last uses after a time (a rank, rankOf) and finds the time of a given rank (at), so either is
// O(log n) for n uses, never a walk of the list. Memory: 8 bytes a use it can hold (the capacity,
// one a point of the page), plus a hash map entry a distinct vector.
#pragma once

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace voxref::ref {

class RecentVectors {
 public:
  // For at most `capacity` uses.
  explicit RecentVectors(std::size_t capacity);
  // Distinct vectors used so far.
  std::uint32_t size() const { return distinct_; }
  // The rank of `key` (0: the most recently used), or nothing when it has not been used.
  std::optional<std::uint32_t> rankOf(std::uint32_t key) const;
  // The vector of rank r < size().
  std::uint32_t at(std::uint32_t rank) const;
  // Uses `key`: its rank becomes 0. At most `capacity` uses (std::logic_error after).
  void use(std::uint32_t key);

 private:
  // The number of last uses at times [0, t].
  std::uint32_t usesUpTo(std::uint32_t t) const;
  void add(std::uint32_t t, int delta);
  std::vector<std::int32_t> tree_;    // Fenwick tree over the times, 1-based
  std::vector<std::uint32_t> keyAt_;  // the vector used at each time
  std::unordered_map<std::uint32_t, std::uint32_t> lastUse_;
  std::uint32_t now_ = 0, distinct_ = 0;
  int topBit_ = 0;  // the highest power of two within the tree's size
};

}  // namespace voxref::ref
