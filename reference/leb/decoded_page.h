// A decoded page as LebReader's page cache keeps it (leb_reader.h, page_cache.h): what it holds,
// how a position is read, and what it costs.
//
// - The deltas of a page of the paper's coders (lead-1, adaptive; FORMAT.md beside this file,
//   "Pages"), added to the point's prediction by the reader (reconstructSample): a delta is a b-bit
//   two's complement value, so a byte each for an 8-bit channel (an 8-bit stream's samples, the
//   gradients) and an int16 each for 16-bit samples. The whole engine's deltas, both channels in
//   pages of 2^12, take 34 MB, within the benches' 64 MB cache (67 MB as int16, docs/leb.md).
// - The values of a context page ("Context pages", "Context gradient pages"): the samples or the
//   gradients' components themselves, a byte each for 8-bit values (an 8-bit stream's samples, the
//   gradients), an int16 each for 16-bit samples. So the engine's pages of both channels at 2^16
//   fit the benches' 64 MB cache (43 MB).
//
// Indices are of values (a point's components one after the other), unchecked: the reader computes
// them from the point's place in its page.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxref::ref {

class DecodedPage {
 public:
  DecodedPage() = default;  // no values
  // `count` deltas of a `valueBits`-bit channel (8 or 16), all 0 until set: a byte each at 8 bits.
  static DecodedPage deltas(std::size_t count, int valueBits) { return DecodedPage(count, valueBits, false); }
  // `count` values of `valueBits` bits (8 or 16), all 0 until set.
  static DecodedPage values(std::size_t count, int valueBits) { return DecodedPage(count, valueBits, true); }

  bool holdsDeltas() const { return !holdsValues_; }
  // A page of deltas: the delta at i.
  std::int16_t delta(std::size_t i) const {
    return bytes_.empty() ? words_[i] : static_cast<std::int16_t>(static_cast<std::int8_t>(bytes_[i]));
  }
  // A page of values: the value at i, an 8-bit one read as int8 when `isSigned` (the gradients).
  std::int32_t value(std::size_t i, bool isSigned) const {
    if (bytes_.empty()) return static_cast<std::uint16_t>(words_[i]);
    return isSigned ? static_cast<std::int32_t>(static_cast<std::int8_t>(bytes_[i])) : std::int32_t{bytes_[i]};
  }
  // The delta or value at i: v in the page's range (a delta of b bits, or a value of b bits, signed
  // or not), kept modulo 2^b.
  void set(std::size_t i, std::int32_t v) {
    if (bytes_.empty())
      words_[i] = static_cast<std::int16_t>(v);
    else
      bytes_[i] = static_cast<std::uint8_t>(v);
  }
  // f(storage): std::uint8_t* to the entries at 8 bits, std::int16_t* at 16, for a writer that sets
  // many (a store of a value in range through it keeps it as set does; no test per entry).
  template <class F>
  void withStorage(F&& f) {
    if (bytes_.empty())
      f(words_.data());
    else
      f(bytes_.data());
  }
  // Values (deltas or values) the page holds.
  std::size_t size() const { return bytes_.empty() ? words_.size() : bytes_.size(); }
  // What the page costs the cache: its values' bytes.
  std::size_t byteSize() const { return words_.size() * sizeof(std::int16_t) + bytes_.size(); }
  bool operator==(const DecodedPage&) const = default;

 private:
  DecodedPage(std::size_t count, int valueBits, bool holdsValues) : holdsValues_(holdsValues) {
    if (valueBits == 8)
      bytes_.assign(count, 0);
    else
      words_.assign(count, 0);
  }
  bool holdsValues_ = false;
  std::vector<std::int16_t> words_;  // 16-bit deltas or values
  std::vector<std::uint8_t> bytes_;  // 8-bit deltas or values
};

}  // namespace voxref::ref
