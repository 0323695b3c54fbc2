// A binary range coder with adaptive bit models: the arithmetic-coding stage of voxref's own
// delta coder (adaptive_delta_coder.h; FORMAT.md, "Adaptive pages").
//
// The coder is the carry-propagating range coder of G. N. N. Martin, "Range encoding: an algorithm
// for removing redundancy from a digitised message" (1979), in the byte-wise form with a 32-bit
// range and a 33-bit low: each bit narrows the range to the part of its probability, and a byte
// leaves whenever the range falls below 2^24. A probability is P(bit = 0) in units of 2^-16,
// kept within [kMinProbability, 2^16 - kMinProbability] so that neither branch is ever empty.
//
// Bit models adapt by a rate that starts at 1/2 and halves after each of the first updates down to
// 2^-kMaxAdaptShift: early on the estimate follows the counts (about as a frequency count would),
// later it forgets old bits exponentially. Every update is integer arithmetic, so encoder and
// decoder hold the same probabilities bit for bit.
//
// The decoder reads untrusted bytes: reading past the end yields zero bytes and marks the
// decoder overrun (the caller turns that into a StreamError), and nothing it decodes can index
// outside its models.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace voxref::ref {

inline constexpr int kProbabilityBits = 16;
inline constexpr std::uint32_t kMinProbability = 32;
inline constexpr int kMaxAdaptShift = 7;

// P(bit = 0) and how many updates it has seen (up to kMaxAdaptShift).
struct BitModel {
  std::uint16_t p0 = 1u << (kProbabilityBits - 1);
  std::uint8_t seen = 0;

  void update(int bit) {
    if (seen < kMaxAdaptShift) ++seen;
    const int shift = seen;  // rates 1/2, 1/4, ... 1/128
    std::int32_t p = p0;
    p += bit ? -(p >> shift) : (((1 << kProbabilityBits) - p) >> shift);
    if (p < static_cast<std::int32_t>(kMinProbability)) p = static_cast<std::int32_t>(kMinProbability);
    if (p > (1 << kProbabilityBits) - static_cast<std::int32_t>(kMinProbability))
      p = (1 << kProbabilityBits) - static_cast<std::int32_t>(kMinProbability);
    p0 = static_cast<std::uint16_t>(p);
  }
};

class RangeEncoder {
 public:
  void encode(BitModel& m, int bit) {
    const std::uint32_t bound = (range_ >> kProbabilityBits) * m.p0;
    if (bit == 0) {
      range_ = bound;
    } else {
      low_ += bound;
      range_ -= bound;
    }
    m.update(bit);
    normalize();
  }
  // n bits of v (n <= 16), most significant first, each with probability 1/2.
  void encodeDirect(std::uint32_t v, int n) {
    for (int i = n - 1; i >= 0; --i) {
      range_ >>= 1;
      if ((v >> i) & 1u) low_ += range_;
      normalize();
    }
  }
  // Ends the page: the bytes that let a decoder take every bit coded so far.
  std::string finish() {
    for (int i = 0; i < 5; ++i) shiftLow();
    return std::move(out_);
  }

 private:
  void normalize() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      shiftLow();
    }
  }
  void shiftLow() {
    if (static_cast<std::uint32_t>(low_) < 0xFF000000u || (low_ >> 32) != 0) {
      const auto carry = static_cast<std::uint8_t>(low_ >> 32);
      std::uint8_t byte = cache_;
      do {
        out_.push_back(static_cast<char>(static_cast<std::uint8_t>(byte + carry)));
        byte = 0xFF;
      } while (--pending_ != 0);
      cache_ = static_cast<std::uint8_t>(low_ >> 24);
    }
    ++pending_;
    low_ = (low_ & 0x00FFFFFFu) << 8;
  }
  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  std::uint64_t pending_ = 1;
  std::string out_;
};

class RangeDecoder {
 public:
  // The first byte of a page is always 0 (the encoder's initial cache): firstByteValid() says so.
  explicit RangeDecoder(std::string_view bytes) : in_(bytes) {
    for (int i = 0; i < 5; ++i) code_ = (code_ << 8) | next();
  }
  bool firstByteValid() const { return !in_.empty() && in_[0] == 0; }

  int decode(BitModel& m) {
    const std::uint32_t bound = (range_ >> kProbabilityBits) * m.p0;
    int bit;
    if (code_ < bound) {
      range_ = bound;
      bit = 0;
    } else {
      code_ -= bound;
      range_ -= bound;
      bit = 1;
    }
    m.update(bit);
    normalize();
    return bit;
  }
  std::uint32_t decodeDirect(int n) {
    std::uint32_t v = 0;
    for (int i = 0; i < n; ++i) {
      range_ >>= 1;
      const std::uint32_t bit = code_ >= range_ ? 1u : 0u;
      if (bit) code_ -= range_;
      v = (v << 1) | bit;
      normalize();
    }
    return v;
  }
  // Bytes taken so far (the encoder's finish() makes a page exactly as long as its decoder takes).
  std::size_t consumed() const { return at_; }
  bool overrun() const { return at_ > in_.size(); }

 private:
  std::uint32_t next() {
    const std::uint32_t b = at_ < in_.size() ? static_cast<std::uint8_t>(in_[at_]) : 0u;
    ++at_;
    return b;
  }
  void normalize() {
    while (range_ < (1u << 24)) {
      range_ <<= 8;
      code_ = (code_ << 8) | next();
    }
  }
  std::string_view in_;
  std::size_t at_ = 0;
  std::uint32_t code_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
};

}  // namespace voxref::ref
