// Bit streams of the LEB codec's pages: most significant bit first (the first code bit is bit 7 of
// the first byte), so that a canonical Huffman code read by table lookup is a prefix of the
// peeked bits (FORMAT.md, section "Page payload").
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace voxref::ref {

class BitWriter {
 public:
  // Appends the low n bits of v (n <= 32), most significant first.
  void put(std::uint32_t v, int n) {
    acc_ = (acc_ << n) | (n == 32 ? v : (v & ((1u << n) - 1)));
    fill_ += n;
    while (fill_ >= 8) {
      fill_ -= 8;
      out_.push_back(static_cast<char>((acc_ >> fill_) & 0xff));
    }
  }
  // Pads the last byte with zero bits and returns the bytes.
  std::string finish() {
    if (fill_ > 0) put(0, 8 - fill_);
    return std::move(out_);
  }
  std::size_t bitCount() const { return out_.size() * 8 + static_cast<std::size_t>(fill_); }

 private:
  std::uint64_t acc_ = 0;
  int fill_ = 0;
  std::string out_;
};

// Reads bits from a byte range. Reading past the end yields zero bits and is remembered: the
// caller checks overrun() (the page decoder turns it into "the page ends inside a code").
class BitReader {
 public:
  explicit BitReader(std::string_view bytes)
      : p_(reinterpret_cast<const unsigned char*>(bytes.data())), size_(bytes.size()) {
    refill();
  }

  // The next n bits (1 <= n <= 32) without consuming them.
  std::uint32_t peek(int n) const { return static_cast<std::uint32_t>(buf_ >> (64 - n)); }
  // Refills after every skip, not only once fewer than 32 bits are left: the lead-1 reader's
  // values take 1 to 10 bits, so a test of what is left branched at no pattern a predictor learns,
  // and a refill of the buffer that still holds its bits changes nothing (docs/leb.md).
  void skip(int n) {
    consume(n);
    refill();
  }
  // skip without the refill, for a caller that refills (refill()) before it can peek past the bits
  // left: a refill leaves at least 56 bits (zeros past the end count), so values whose lengths sum
  // to at most 56 can be peeked and consumed between two refills.
  void consume(int n) {
    buf_ <<= n;
    avail_ -= n;
  }
  std::uint32_t get(int n) {
    if (n == 0) return 0;
    const std::uint32_t v = peek(n);
    skip(n);
    return v;
  }
  // The bits taken so far: every refill adds to buf_ exactly the bits of the bytes it counts in
  // next_, so those are the consumed ones and the avail_ still in buf_.
  std::size_t bitsConsumed() const { return 8 * next_ - static_cast<std::size_t>(avail_); }
  bool overrun() const { return bitsConsumed() > size_ * 8; }
  // Tops the buffer up to at least 56 bits.
  void refill() {
    if (next_ + 8 <= size_) {
      // Eight bytes at once, most significant first. Bits beyond the whole bytes counted are the
      // stream's own next bits, so OR-ing them in again at the next refill changes nothing.
      std::uint64_t w;
      std::memcpy(&w, p_ + next_, 8);
      if constexpr (std::endian::native == std::endian::little) w = __builtin_bswap64(w);
      buf_ |= w >> avail_;
      const int bytes = (63 - avail_) >> 3;
      next_ += static_cast<std::size_t>(bytes);
      avail_ += 8 * bytes;
      return;
    }
    while (avail_ <= 56) {
      const std::uint64_t byte = next_ < size_ ? p_[next_] : 0;
      ++next_;
      buf_ |= byte << (56 - avail_);
      avail_ += 8;
    }
  }

 private:
  const unsigned char* p_;
  std::size_t size_;
  std::size_t next_ = 0;
  std::uint64_t buf_ = 0;
  int avail_ = 0;  // valid bits at the top of buf_ (zeros past the end count as valid)
};

}  // namespace voxref::ref
