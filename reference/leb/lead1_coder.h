// Lead-1 coding of prediction deltas with one symbol of context (Gregorski et al. 2004, section
// 3.1).
//
// A delta is a b-bit two's complement value d (b = 8 or 16). Its symbol is the position of the
// leading one of |d| counted from 1 (0 for d = 0), so b + 1 symbols. A delta is written as the
// Huffman code of its symbol in the table of the previous symbol (the context; 0 at the start of
// every page), then, if d != 0, the sign bit (1 = negative) and the symbol - 1 bits of |d| below
// its leading one, most significant first. |d| = 2^(b-1) occurs only with the sign bit set
// (d = -2^(b-1)); a stream holding +2^(b-1) is not one the encoder writes and is rejected.
//
// The decoder is for untrusted bytes: any code that matches no symbol, a page that ends inside a
// value, a magnitude outside the b-bit range, or bits left over beyond the zero padding of the last
// byte throw StreamError with the byte offset.
#pragma once

#include <bit>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "reference/leb/bit_stream.h"
#include "reference/leb/huffman.h"

namespace voxref::ref {

inline int lead1Symbol(std::int32_t delta) {
  return std::bit_width(static_cast<std::uint32_t>(delta < 0 ? -static_cast<std::int64_t>(delta) : delta));
}

// The code lengths of every context: lengths[context * symbols() + symbol].
struct Lead1Code {
  int valueBits = 8;
  std::vector<std::uint8_t> lengths;
  int symbols() const { return valueBits + 1; }
};

// Counts (context, symbol) pairs of delta sequences; the context restarts at every sequence
// (page). The lengths built from the counts code exactly those sequences.
class Lead1Counter {
 public:
  explicit Lead1Counter(int valueBits);
  void add(std::span<const std::int32_t> page);
  void merge(const Lead1Counter& other);
  Lead1Code code() const;  // package-merge lengths per context (huffman.h)

 private:
  int valueBits_;
  std::vector<std::uint64_t> counts_;
};

// Why a code cannot be used ("" when it can), naming the context: see codeLengthProblem.
std::string lead1CodeProblem(const Lead1Code& code);

class Lead1Encoder {
 public:
  explicit Lead1Encoder(const Lead1Code& code);
  // Appends the deltas of one page (context restarting at 0). Throws std::invalid_argument for a
  // delta outside the b-bit range or a symbol the code has no length for.
  void encodePage(std::span<const std::int32_t> deltas, BitWriter& out) const;

 private:
  int valueBits_;
  int symbols_;
  std::vector<std::uint8_t> lengths_;
  std::vector<std::uint32_t> codes_;
};

// A value's s > 0 sign-and-magnitude bits (FORMAT.md, "Page payload"): the sign bit first, then the
// magnitude's bits below its leading 1. One definition for the one-lookup entries and the table
// path, so the two cannot disagree.
struct Lead1SignMagnitude {
  bool negative;
  std::uint32_t magnitude;
  std::int32_t delta() const {
    return negative ? -static_cast<std::int32_t>(magnitude) : static_cast<std::int32_t>(magnitude);
  }
  // |delta| fits valueBits two's complement (+2^(b-1) does not).
  bool fits(int valueBits) const {
    const std::uint32_t limit = 1u << (valueBits - 1);
    return !(magnitude > limit || (magnitude == limit && !negative));
  }
};
inline Lead1SignMagnitude lead1SignMagnitude(std::uint32_t bits, int s) {
  const std::uint32_t lead = 1u << (s - 1);
  return {(bits & lead) != 0, lead | (bits & (lead - 1))};
}

class Lead1Decoder {
 public:
  explicit Lead1Decoder(const Lead1Code& code);  // throws std::invalid_argument when lead1CodeProblem != ""
  // Decodes exactly out.size() deltas from one page's bytes (Lead1PageReader, then finish()).
  // `streamOffset` is the offset of the page's first byte in the whole stream and `what` names
  // the page ("data page 17"): both go into the StreamError messages.
  void decodePage(std::string_view page, std::span<std::int32_t> out, std::size_t streamOffset,
                  std::string_view what) const;

  // One lookup per value, or per two: fastEntry(context, next kFastBits bits) is
  //   - 0 where the code is longer than kFastBits, no code matches, or the symbol is valueBits
  //     (the only one whose magnitude can be out of range): the reader then takes the table path,
  //     which checks and names the problem;
  //   - else, without kPair, one value: its length (its code, sign and magnitude bits; bits 0-4),
  //     its symbol (the next context; bits 5-9) and, where the whole value lies in the peeked bits
  //     (kWholeValue set), its delta (bits 16-31, two's complement); otherwise the delta follows
  //     from the value's bits (fastDelta). deltaOf gives it either way;
  //   - with kPair, two values that both lie in the peeked bits, the second coded in the
  //     context of the first: their length together (bits 0-4), the second's symbol (bits 5-9)
  //     and their deltas (pairFirst, bits 12-21, and pairSecond, bits 22-31: a value of at most
  //     kFastBits bits has a symbol below kFastBits, so |delta| < 2^9).
  static constexpr int kFastBits = 10;
  static constexpr std::uint32_t kWholeValue = 1u << 10, kPair = 1u << 11;
  std::uint32_t fastEntry(int context, std::uint32_t peeked) const {
    return fast_[(static_cast<std::size_t>(context) << kFastBits) | peeked];
  }
  static int symbolOf(std::uint32_t e) { return static_cast<int>((e >> 5) & 31); }
  // How many one-lookup entries can follow each other between two refills of a BitReader (which
  // leaves at least 56 bits): 56 over the longest entry's length (e & 31), at least 1.
  int lookupsPerRefill() const { return lookupsPerRefill_; }
  // The delta of a one-value entry e whose value starts at the reader's next bit.
  static std::int32_t deltaOf(std::uint32_t e, const BitReader& in) {
    return (e & kWholeValue) ? wholeDelta(e) : fastDelta(e, in.peek(static_cast<int>(e & 31)));
  }
  static std::int32_t wholeDelta(std::uint32_t e) { return static_cast<std::int32_t>(e) >> 16; }
  static std::int32_t pairFirst(std::uint32_t e) { return static_cast<std::int32_t>(e << 10) >> 22; }
  static std::int32_t pairSecond(std::uint32_t e) { return static_cast<std::int32_t>(e) >> 22; }
  // The delta of a fast entry e from the value's bits (the next e & 31 bits of the page): the low
  // s = symbol bits are the sign and magnitude (lead1SignMagnitude).
  static std::int32_t fastDelta(std::uint32_t e, std::uint32_t valueBitsPeeked) {
    const int s = symbolOf(e);
    return s == 0 ? 0 : lead1SignMagnitude(valueBitsPeeked & ((1u << s) - 1), s).delta();
  }

 private:
  friend class Lead1PageReader;
  int valueBits_;
  int symbols_;
  std::vector<HuffmanDecodeTable> tables_;
  std::vector<std::uint32_t> fast_;
  int lookupsPerRefill_ = 1;
};

// Reads the deltas of one page one at a time, for a decoder that does not know in advance how
// many the page holds (the whole-volume decoder walks the grid and asks for a delta per point).
// The decoder must outlive the reader.
class Lead1PageReader {
 public:
  Lead1PageReader(const Lead1Decoder& decoder, std::string_view page, std::size_t streamOffset, std::string what);
  // Throws StreamError: no code matches, the page ends, a delta out of range.
  std::int32_t next() {
    const std::uint32_t e = decoder_->fastEntry(context_, in_.peek(Lead1Decoder::kFastBits));
    if (e == 0 || (e & Lead1Decoder::kPair)) [[unlikely]]  // one value at a time: a pair's first by the table
      return nextByTable();
    const std::int32_t d = Lead1Decoder::deltaOf(e, in_);
    in_.skip(static_cast<int>(e & 31));
    if (in_.overrun()) [[unlikely]]
      fail("the page ends inside this value");
    ++read_;
    context_ = Lead1Decoder::symbolOf(e);
    return d;
  }
  // The next out.size() values: the same values and errors as that many next() calls, faster (the
  // bit buffer stays in registers between values that the one lookup decodes).
  void read(std::span<std::int32_t> out);
  // a.read(outA), then b.read(outB): the same values and errors (a's first), faster on one thread.
  // Each reader's lookups form a chain (a value's length decides where the next one starts); the
  // two pages' chains are independent, so they run interleaved.
  static void readBoth(Lead1PageReader& a, std::span<std::int32_t> outA, Lead1PageReader& b,
                       std::span<std::int32_t> outB);
  void finish() const;  // throws StreamError unless only the zero padding of the last byte is left
  std::size_t valuesRead() const { return read_; }

 private:
  std::int32_t nextByTable();  // the code by its table, then sign and magnitude
  // The value (or pair) of a nonzero fast entry e into out[i] (and out[i + 1]), past its bits.
  // Refill false: the caller refills (lookupRuns, lookupRunsBoth).
  template <bool Refill = true>
  static void fastStep(std::uint32_t e, BitReader& in, int& context, std::int32_t* out, std::size_t& i) {
    if (e & Lead1Decoder::kPair) {
      out[i] = Lead1Decoder::pairFirst(e);
      out[i + 1] = Lead1Decoder::pairSecond(e);
      i += 2;
    } else {
      out[i++] = Lead1Decoder::deltaOf(e, in);
    }
    if constexpr (Refill)
      in.skip(static_cast<int>(e & 31));
    else
      in.consume(static_cast<int>(e & 31));
    context = Lead1Decoder::symbolOf(e);
  }
  // read's runs of one-lookup values, K lookups between two refills of the bits, while the output
  // has room for K pairs; stops before a lookup that needs the table path.
  template <int K>
  static void lookupRuns(const Lead1Decoder& d, BitReader& in, int& context, std::span<std::int32_t> out,
                         std::size_t& i);
  // The same for two pages at once (readBoth), while both have room.
  template <int K>
  static void lookupRunsBoth(const Lead1Decoder& da, BitReader& inA, int& contextA, std::span<std::int32_t> outA,
                             std::size_t& i, const Lead1Decoder& db, BitReader& inB, int& contextB,
                             std::span<std::int32_t> outB, std::size_t& j);
  // Takes over the state after a run of `values` one-lookup values decoded on local copies.
  void commitRun(const BitReader& in, int context, std::size_t values) {
    in_ = in;
    context_ = context;
    read_ += values;
  }
  [[noreturn]] void fail(const std::string& detail) const;
  const Lead1Decoder* decoder_;
  std::string_view page_;
  BitReader in_;
  std::size_t streamOffset_;
  std::string what_;
  int context_ = 0;
  std::size_t read_ = 0;
};

}  // namespace voxref::ref
