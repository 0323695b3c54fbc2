// The binary decisions of one signed value (a prediction delta or residual) under a range coder:
// the coding step that voxref's two coders of their own share, the adaptive coder of the paper's
// deltas (adaptive_delta_coder.h; FORMAT.md, "Adaptive pages") and the context coder of values
// (context_value_coder.h; FORMAT.md, "Context pages"). They differ in their models' contexts only.
//
// A value d of b bits is coded as
//   1. zero:     d == 0, model zero(context);
//   2. symbol:   s = bit width of |d| (1..b), s - 1 as treeDepth() bits, most significant first,
//                down a binary tree of models tree(context, node), node 1 at the root;
//   3. sign:     1 = negative, model sign(signContext, s);
//   4. mantissa: the s - 1 bits of |d| below its leading one, most significant first: the first two
//                with models mantissa(signContext, s, prefix) (prefix 0 for the first bit, 1 + that
//                bit for the second), the rest direct (probability 1/2).
// One function serves the encoder and the decoder, so both make the same decisions with the same
// models in the same order.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "reference/leb/range_coder.h"

namespace voxref::ref {

// The models of one page's decisions, all at their initial state (made afresh for every page):
// `contexts` contexts of the zero flag and of the symbol tree, `signContexts` of the sign and of the
// mantissa (each by symbol). The coders choose the contexts: the adaptive coder's are the previous
// symbols and the component, the context coder's the corners and the neighbours. valueBits is 8
// or 16 (the caller checks it, with its own message).
class DeltaDecisionModels {
 public:
  DeltaDecisionModels(int valueBits, int contexts, int signContexts)
      : valueBits_(valueBits),
        treeDepth_(valueBits == 16 ? 4 : 3),
        zero_(static_cast<std::size_t>(contexts)),
        tree_(static_cast<std::size_t>(contexts) * 16),
        sign_(static_cast<std::size_t>(signContexts) * 17),
        mantissa_(static_cast<std::size_t>(signContexts) * 17 * 3) {}
  int valueBits() const { return valueBits_; }
  int treeDepth() const { return treeDepth_; }
  BitModel& zero(int context) { return zero_[static_cast<std::size_t>(context)]; }
  BitModel& tree(int context, int node) { return tree_[static_cast<std::size_t>(context) * 16 + node]; }
  BitModel& sign(int signContext, int symbol) { return sign_[static_cast<std::size_t>(signContext) * 17 + symbol]; }
  BitModel& mantissa(int signContext, int symbol, int prefix) {
    return mantissa_[(static_cast<std::size_t>(signContext) * 17 + symbol) * 3 + prefix];
  }

 private:
  int valueBits_, treeDepth_;
  std::vector<BitModel> zero_, tree_, sign_, mantissa_;
};

// The encoder's bits: each decision is the value's own.
struct EncodeBits {
  RangeEncoder& out;
  int bit(BitModel& m, int b) {
    out.encode(m, b);
    return b;
  }
  std::uint32_t direct(std::uint32_t v, int n) {
    out.encodeDirect(v, n);
    return v;
  }
};
// The decoder's bits: each decision is read (the value arguments are ignored).
struct DecodeBits {
  RangeDecoder& in;
  int bit(BitModel& m, int) { return in.decode(m); }
  std::uint32_t direct(std::uint32_t, int n) { return in.decodeDirect(n); }
};

// Codes one value: returns its symbol s (0 for zero) and sets `negative` and `magnitude` (decoding)
// or takes them (encoding; `symbol` is then the value's symbol).
template <class Bits>
int codeDeltaDecisions(Bits bits, DeltaDecisionModels& m, int context, int signContext, int symbol, int& negative,
                       std::uint32_t& magnitude) {
  if (bits.bit(m.zero(context), symbol == 0 ? 0 : 1) == 0) return 0;
  // The symbol: s - 1 as a binary tree, most significant bit first.
  int node = 1;
  for (int level = m.treeDepth() - 1; level >= 0; --level)
    node = 2 * node + bits.bit(m.tree(context, node), ((symbol - 1) >> level) & 1);
  const int s = node - (1 << m.treeDepth()) + 1;
  negative = bits.bit(m.sign(signContext, s), negative);
  // The mantissa below the leading one.
  const int rest = s - 1;
  std::uint32_t below = 0;
  int prefix = 0;
  for (int i = rest - 1; i >= 0 && rest - 1 - i < 2; --i) {
    const int b = bits.bit(m.mantissa(signContext, s, prefix), static_cast<int>((magnitude >> i) & 1u));
    below = (below << 1) | static_cast<std::uint32_t>(b);
    prefix = 1 + b;
  }
  const int direct = std::max(rest - 2, 0);
  below = (below << direct) | bits.direct(magnitude & ((1u << direct) - 1), direct);
  magnitude = (1u << rest) | below;
  return s;
}

// Codes a positive integer q by its bit width w: w - 1 as `levels` binary decisions down a tree of
// models tree(node) (node 1 at the root, then 2 node + the bit; nodes below 2^levels), most
// significant first, then the w - 1 bits of q below its leading one, direct (probability 1/2), most
// significant first, sixteen at a time. Returns q: the encoder's (which must have w <= 2^levels),
// or the one read (the encoder's argument is then ignored). The gaps of a mirrored stream's
// exceptions (mirror_stream.cpp) and the ranks of a gradient page's recent vectors
// (context_gradient_coder.cpp) are coded so.
template <class Bits, class Tree>
std::uint64_t codeByBitWidth(Bits bits, Tree&& tree, int levels, std::uint64_t q) {
  const int w = q == 0 ? 1 : static_cast<int>(std::bit_width(q));
  int node = 1;
  for (int level = levels - 1; level >= 0; --level) node = 2 * node + bits.bit(tree(node), ((w - 1) >> level) & 1);
  const int width = node - (1 << levels) + 1;
  std::uint64_t v = 1;
  for (int left = width - 1; left > 0;) {
    const int n = left < 16 ? left : 16;
    left -= n;
    v = (v << n) | bits.direct(static_cast<std::uint32_t>((q >> left) & ((1u << n) - 1)), n);
  }
  return v;
}

}  // namespace voxref::ref
