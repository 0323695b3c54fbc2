// A hash map from 64-bit keys to small values, in one flat array (open addressing, linear
// probing): the memo and vertex maps of the isosurface path, which do millions of lookups and
// insertions a frame. std::unordered_map allocates a node per entry, and that allocation was the
// largest single cost of extraction.
//
// Contract: any key except kEmptyKey (all ones; try_emplace throws std::invalid_argument for it);
// find, try_emplace and erase are amortized O(1); the table doubles when it is half full, so it holds at
// most 4 slots per entry (16 + 4 sizeof(V) bytes per entry at worst, plus the empty table's 16
// slots), and 6 while it doubles (the old table and the new one); a table reserved for n entries
// never doubles before it holds n; erase never shrinks it. References returned by find and
// try_emplace are valid until the next try_emplace, erase or clear. Iteration is not offered: results cannot depend on
// the table's order. Not thread-safe.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace voxref::ref {

template <class V>
class FlatU64Map {
 public:
  static constexpr std::uint64_t kEmptyKey = ~std::uint64_t{0};

  FlatU64Map() { clear(); }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // The value under `key`, or null.
  const V* find(std::uint64_t key) const {
    for (std::size_t i = slotOf(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return &values_[i];
      if (keys_[i] == kEmptyKey) return nullptr;
    }
  }
  V* find(std::uint64_t key) { return const_cast<V*>(std::as_const(*this).find(key)); }

  // Inserts `value` under `key` unless the key is there; returns the value under the key and
  // whether it was inserted.
  std::pair<V&, bool> try_emplace(std::uint64_t key, const V& value) {
    if (key == kEmptyKey) throw std::invalid_argument("FlatU64Map: the key 2^64 - 1 is reserved");
    if (2 * (size_ + 1) > keys_.size()) grow();
    std::size_t i = slotOf(key);
    for (; keys_[i] != kEmptyKey; i = (i + 1) & mask_)
      if (keys_[i] == key) return {values_[i], false};
    keys_[i] = key;
    values_[i] = value;
    ++size_;
    return {values_[i], true};
  }

  // Removes `key` and its value; returns whether it was there. Backward-shift deletion (Knuth,
  // TAOCP vol. 3, section 6.4, Algorithm R): the entries after it in its probe run move up into
  // the hole unless their home slot lies cyclically after it, so no tombstones are left and every
  // remaining key is still found from its home slot.
  bool erase(std::uint64_t key) {
    if (key == kEmptyKey) return false;
    std::size_t hole = slotOf(key);
    for (; keys_[hole] != key; hole = (hole + 1) & mask_)
      if (keys_[hole] == kEmptyKey) return false;
    for (std::size_t j = (hole + 1) & mask_; keys_[j] != kEmptyKey; j = (j + 1) & mask_) {
      const std::size_t home = slotOf(keys_[j]);
      // The entry at j stays when its home lies cyclically in (hole, j].
      const bool stays = hole <= j ? (hole < home && home <= j) : (hole < home || home <= j);
      if (stays) continue;
      keys_[hole] = keys_[j];
      values_[hole] = std::move(values_[j]);
      hole = j;
    }
    keys_[hole] = kEmptyKey;
    values_[hole] = V{};
    --size_;
    return true;
  }

  // Sizes the table for n entries at once (at most 4n slots, 16 at least); only on an empty map.
  void reserve(std::size_t n) {
    if (size_ != 0) throw std::logic_error("FlatU64Map: reserve on a map that holds entries");
    reset(n);
  }

  // Empties the map and sizes its table for n entries as reserve does, keeping the memory it has
  // where that is enough (a map rebuilt every frame then allocates, and faults, only as it grows).
  void reset(std::size_t n) {
    const std::size_t slots = std::max(kMinSlots, std::bit_ceil(2 * n));
    keys_.assign(slots, kEmptyKey);
    values_.assign(slots, V{});
    resized();
    size_ = 0;
  }

  // Empties the map and gives its memory back (the table returns to 16 slots).
  void clear() {
    keys_.assign(kMinSlots, kEmptyKey);
    keys_.shrink_to_fit();
    values_.assign(kMinSlots, V{});
    values_.shrink_to_fit();
    resized();
    size_ = 0;
  }

 private:
  static constexpr std::size_t kMinSlots = 16;

  // Fibonacci hashing (Knuth, TAOCP vol. 3, section 6.4): the top bits of key * 2^64 / phi, so
  // keys that differ in their low bits only (neighbouring grid indices) spread over the table.
  std::size_t slotOf(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >> shift_) & mask_;
  }

  void grow() {
    std::vector<std::uint64_t> keys(keys_.size() * 2, kEmptyKey);
    std::vector<V> values(keys.size());
    keys.swap(keys_);
    values.swap(values_);
    resized();
    for (std::size_t j = 0; j < keys.size(); ++j) {
      if (keys[j] == kEmptyKey) continue;
      std::size_t i = slotOf(keys[j]);
      while (keys_[i] != kEmptyKey) i = (i + 1) & mask_;
      keys_[i] = keys[j];
      values_[i] = values[j];
    }
  }

  // The mask and shift of a table of keys_.size() slots (a power of two).
  void resized() {
    mask_ = keys_.size() - 1;
    shift_ = 64 - std::countr_zero(keys_.size());
  }

  std::vector<std::uint64_t> keys_;
  std::vector<V> values_;
  std::size_t mask_ = 0;
  int shift_ = 64;  // 64 - log2(slots)
  std::size_t size_ = 0;
};

}  // namespace voxref::ref
