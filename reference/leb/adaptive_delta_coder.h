// voxref's own entropy stage for the LEB codec's prediction deltas (Gregorski et al. 2004, section
// 3.1 gives the deltas; this coder replaces only the lead-1 Huffman code of them): each page is
// coded on its own by a binary range coder (range_coder.h) whose bit models adapt within the page,
// so pages keep their random access and no code table is stored. FORMAT.md beside this file,
// "Adaptive pages", is the definition; this is its implementation.
//
// A delta d of b bits (b = 8 or 16) is written as decisions, each with a model of its own:
//   1. zero:      d == 0, in the context of the page's previous two deltas;
//   2. symbol:    s = bit width of |d| (1..b), s - 1 as log2(b) bits of a binary tree, in the same
//                 context;
//   3. sign:      1 = negative, in the context (component, s);
//   4. mantissa:  the s - 1 bits of |d| below its leading one; the first two adaptively in the
//                 context (component, s, bits so far), the rest with probability 1/2.
// The context of delta i is its component (i mod components) and the symbols of deltas i - 1 and
// i - components (i - 2 for the data channel), each capped at kAdaptiveSymbolCap; symbols before
// the page's first delta count as 0. The lead-1 code is the paper's and stays the default; a
// stream of this coder is version 3 (LebEncodeOptions::coder, voxref encode --coder adaptive), and
// voxref bench --filter leb.coder measures the two side by side.
//
// The decoder is for untrusted bytes: a page whose first byte is not 0, that ends inside a value,
// that holds +2^(b-1), or has bytes left after its last value throws StreamError with the byte
// offset and the page's name.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "reference/leb/delta_decisions.h"
#include "reference/leb/range_coder.h"

namespace voxref::ref {

inline constexpr int kAdaptiveSymbolCap = 7;
// No page holds more deltas per byte than this: every delta costs at least its zero decision, and
// a decision keeps at most 1 - (255/256)(32/2^16) of the range (the probability floor, less what
// truncating the range to 16 bits can add), over 7.0e-4 bits, so at most about 11,400 deltas a
// byte. The stream parser refuses payloads too short for their volume by it (leb_stream.cpp).
inline constexpr std::uint64_t kAdaptiveDeltasPerByteBound = 16384;

// The models of one page (delta_decisions.h), all at their initial state: made afresh for every
// page. 64 contexts a component for the zero flag and the symbol; the component is the sign's and
// the mantissa's context.
class AdaptiveDeltaModels : public DeltaDecisionModels {
 public:
  AdaptiveDeltaModels(int valueBits, int components);
  int components() const { return components_; }

 private:
  int components_;
};

// Tracks the symbols of the deltas coded so far and gives the context of the next one.
class AdaptiveContext {
 public:
  explicit AdaptiveContext(int components) : components_(components) {}
  int next() const;  // the context of the next delta
  void push(int symbol);

 private:
  int components_;
  std::size_t at_ = 0;
  std::uint8_t history_[4] = {0, 0, 0, 0};  // symbols of the last deltas, capped; ring of 4
};

// The bytes of one page: deltas, b-bit two's complement values, components interleaved per
// point. Throws std::invalid_argument for a delta outside the b-bit range, or for valueBits other
// than 8 or 16 or components other than 1 or 3.
std::string encodeAdaptivePage(std::span<const std::int32_t> deltas, int valueBits, int components);

// Reads the deltas of one page one at a time (as Lead1PageReader does for the paper's code).
class AdaptivePageReader {
 public:
  // `streamOffset` is the offset of the page's first byte in the stream and `what` names the page
  // ("data page 17"): both go into the StreamError messages. The page's bytes must outlive the
  // reader. Throws StreamError for a page shorter than 5 bytes or whose first byte is not 0.
  AdaptivePageReader(std::string_view page, int valueBits, int components, std::size_t streamOffset, std::string what);
  std::int32_t next();
  void read(std::span<std::int32_t> out) {
    for (std::int32_t& d : out) d = next();
  }
  void finish() const;  // throws StreamError unless the page's bytes are used up exactly
  std::size_t valuesRead() const { return read_; }

 private:
  [[noreturn]] void fail(const std::string& detail) const;
  AdaptiveDeltaModels models_;
  AdaptiveContext context_;
  RangeDecoder in_;
  std::size_t pageBytes_, streamOffset_;
  std::string what_;
  std::size_t read_ = 0;
};

}  // namespace voxref::ref
