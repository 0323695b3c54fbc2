// The move-to-front list of a gradient page's vectors (recent_vectors.h). The Fenwick tree is that
// of P. M. Fenwick, "A new data structure for cumulative frequency tables" (1994): prefix counts
// and the search for a prefix count, each one step per bit of the index.
#include "reference/leb/recent_vectors.h"

#include <stdexcept>

namespace voxref::ref {

RecentVectors::RecentVectors(std::size_t capacity) : tree_(capacity + 1, 0), keyAt_(capacity, 0) {
  while ((std::size_t{2} << topBit_) <= capacity) ++topBit_;
}

std::uint32_t RecentVectors::usesUpTo(std::uint32_t t) const {
  std::int64_t n = 0;
  for (std::size_t i = std::size_t{t} + 1; i > 0; i &= i - 1) n += tree_[i];
  return static_cast<std::uint32_t>(n);
}

void RecentVectors::add(std::uint32_t t, int delta) {
  for (std::size_t i = std::size_t{t} + 1; i < tree_.size(); i += i & (~i + 1)) tree_[i] += delta;
}

std::optional<std::uint32_t> RecentVectors::rankOf(std::uint32_t key) const {
  const auto it = lastUse_.find(key);
  if (it == lastUse_.end()) return std::nullopt;
  return distinct_ - usesUpTo(it->second);  // the last uses after its own
}

std::uint32_t RecentVectors::at(std::uint32_t rank) const {
  // The time of the (distinct - rank)-th last use, counted from the earliest: the largest index
  // whose prefix count is below it, plus one.
  std::uint32_t left = distinct_ - rank;
  std::size_t i = 0;
  for (int b = topBit_; b >= 0; --b) {
    const std::size_t next = i + (std::size_t{1} << b);
    if (next < tree_.size() && static_cast<std::uint32_t>(tree_[next]) < left) {
      i = next;
      left -= static_cast<std::uint32_t>(tree_[next]);
    }
  }
  return keyAt_[i];  // tree index i + 1 is time i
}

void RecentVectors::use(std::uint32_t key) {
  if (now_ >= keyAt_.size()) throw std::logic_error("RecentVectors: more uses than its capacity");
  const auto [it, added] = lastUse_.try_emplace(key, now_);
  if (added)
    ++distinct_;
  else {
    add(it->second, -1);
    it->second = now_;
  }
  add(now_, +1);
  keyAt_[now_] = key;
  ++now_;
}

}  // namespace voxref::ref
