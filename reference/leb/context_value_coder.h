// voxref's context coder of an LEB stream's samples (FORMAT.md beside this file, "Context pages",
// version 4; issue 18, goal 5: beyond the paper's ratio while keeping page random access).
//
// The paper's codec (Gregorski et al. 2004, section 3.1) predicts a point from its split edge and
// codes the delta; lead-1 and the adaptive coder code those deltas with contexts from the page's
// previous deltas only. This coder predicts a point of scale h from all of its corners (the points
// at +-h on its odd axes: they lie on the lattice of 2h, so they are coarser than every point of
// scale h) and codes the residual with contexts from those corners' values (their range) and from
// the residuals of the point's three neighbours of its own class at -2h that lie in the same page.
// A page therefore decodes given the values of the coarser points its points' corners name: the
// points that reconstructing any of its points reads anyway (random access, leb_reader.h, decodes
// them through their own pages). Nothing of a page depends on another page of its own scale.
//
// The values are the samples themselves (8 or 16 bits), not the paper's deltas; a stream of this
// coder stores its gradients, if it has them and does not derive them (FORMAT.md, header byte 23),
// in pages of their own (context_gradient_coder.h). The decisions per residual are
// delta_decisions.h's, with this coder's contexts.
//
// The decoder is for untrusted bytes: a page whose first byte is not 0, that ends inside a value,
// holds a residual of +2^(b-1), or has bytes left after its last value throws StreamError with the
// byte offset and the page's name.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "reference/common/volume.h"
#include "reference/leb/delta_decisions.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/lead1_coder.h"
#include "reference/leb/prediction.h"

namespace voxref::ref {

inline constexpr int kContextRangeBuckets = 8;   // the corners' range, bucketed (contextRangeBucket)
inline constexpr int kContextNeighbourSums = 8;  // the neighbours' symbols summed, capped at 7
inline constexpr int kContextSignContexts = 7;   // the neighbours' signs summed, clamped to [-3, 3]
// The page's models (delta_decisions.h): context = neighbour sum x 8 + range bucket, sign context
// = the neighbours' sign sum + 3.
inline constexpr int kContextContexts = kContextRangeBuckets * kContextNeighbourSums;

// 0 for a range of 0, else min(7, 1 + ceil(log2 range)): 1, 2, 3..4, 5..8, 9..16, 17..32, > 32.
inline int contextRangeBucket(std::int32_t range) {
  if (range <= 0) return 0;
  return std::min(kContextRangeBuckets - 1,
                  1 + static_cast<int>(std::bit_width(static_cast<std::uint32_t>(range - 1))));
}

// Calls f(q) for each corner of p (scale 2^scaleLog2, odd axes oddAxes, not a root corner) that
// lies inside the volume `dims`: of the 2^n points at +-h on its n odd axes, those inside (the one
// at -h on every odd axis always is), in the order of c = 0 .. 2^n - 1 (bit i of c: +h on the
// i-th odd axis). Returns how many it called f for. The data's and the gradients' predictions
// (context_gradient_coder.h) both walk the corners with it.
template <class F>
int forEachCornerInside(const GridPoint& p, int scaleLog2, unsigned oddAxes, const Dims3& dims, F&& f) {
  const int h = 1 << scaleLog2;
  int axes[3], n = 0;
  unsigned plusInside = 0;  // bit i: the corner at +h on odd axis i lies inside the volume
  for (int a = 0; a < 3; ++a)
    if ((oddAxes >> a) & 1u) {
      if (p[a] + h < dims[a]) plusInside |= 1u << n;
      axes[n++] = a;
    }
  int m = 0;
  for (unsigned c = 0; c < (1u << n); ++c) {
    if (c & ~plusInside) continue;  // +h on an axis where that leaves the volume
    GridPoint q = p;
    for (int i = 0; i < n; ++i) q[axes[i]] += ((c >> i) & 1u) ? h : -h;
    f(q);
    ++m;
  }
  return m;
}

// The rounded mean and the range of m > 0 corner values (their sum, minimum and maximum).
struct CornerPrediction {
  std::int32_t prediction = 0;
  int rangeBucket = 0;
};
inline CornerPrediction cornerMean(std::int64_t sum, std::int32_t lo, std::int32_t hi, int m) {
  return {static_cast<std::int32_t>((sum + m / 2) / m), contextRangeBucket(hi - lo)};
}

// A point's prediction from its corners and the bucket of their range: over the m corners inside
// the volume (forEachCornerInside), valueOf(q) giving a corner's value (>= 0),
// prediction = floor((sum + floor(m / 2)) / m), range = their maximum - their minimum.
template <class ValueOf>
CornerPrediction cornerPrediction(const GridPoint& p, int scaleLog2, unsigned oddAxes, const Dims3& dims,
                                  ValueOf&& valueOf) {
  std::int64_t sum = 0;
  std::int32_t lo = 0, hi = 0;
  bool first = true;
  const int m = forEachCornerInside(p, scaleLog2, oddAxes, dims, [&](const GridPoint& q) {
    const std::int32_t v = valueOf(q);
    sum += v;
    lo = first ? v : std::min(lo, v);
    hi = first ? v : std::max(hi, v);
    first = false;
  });
  return cornerMean(sum, lo, hi, m);
}

// What one page's coding keeps between its points: the models, and the symbol and sign of every
// residual coded so far, by the point's place in the page (for the neighbours' contexts).
class ContextPageState {
 public:
  // Throws std::invalid_argument for value bits other than 8 or 16.
  ContextPageState(int valueBits, int pageBits, std::uint64_t page);
  DeltaDecisionModels& models() { return models_; }
  std::uint64_t pageBegin() const { return begin_; }
  struct Contexts {
    int context = 0, signContext = 3;
  };
  // The contexts of p (index h, class c, not a root corner) whose corners' range falls in rangeBucket: its
  // neighbours q = p - 2h on each axis (q_a >= 0) whose index lies in this page count with the
  // residual recorded for them (none yet: 0).
  Contexts contexts(const HzOrder& order, std::uint64_t h, const GridPoint& p, const LebPointClass& c,
                    int rangeBucket) const;
  void record(std::uint64_t h, int symbol, bool negative);

 private:
  DeltaDecisionModels models_;
  std::uint64_t begin_;
  std::vector<std::int8_t> signedSymbol_;  // by place in the page: symbol, negated for a negative residual
};

// The context and sign context of a point: a root corner's (prediction 0, no corners, no
// neighbours), else from its corners and neighbours; and its prediction.
struct ContextPoint {
  std::int32_t prediction = 0;
  ContextPageState::Contexts contexts;
};
template <class ValueOf>
ContextPoint contextPoint(const HzOrder& order, const Dims3& dims, const ContextPageState& state, std::uint64_t h,
                          const GridPoint& p, int level, int scaleLog2, unsigned oddAxes, ValueOf&& valueOf) {
  if (level < 0) return {};
  const CornerPrediction cp = cornerPrediction(p, scaleLog2, oddAxes, dims, valueOf);
  const LebPointClass c{level, scaleLog2, std::popcount(oddAxes) - 1, oddAxes};
  return {cp.prediction, state.contexts(order, h, p, c, cp.rangeBucket)};
}

// One value's residual under the models m (their value bits b): r = (value - prediction) mod 2^b,
// read as a b-bit two's complement value, and its decisions (delta_decisions.h) with contexts ctx,
// in one function for the encoder (EncodeBits: `value` is coded) and the decoder (DecodeBits:
// `value` is ignored, the result's value is read). The samples' coder and the gradients'
// components (context_gradient_coder.h) both code their values with it.
struct ContextResidual {
  std::int32_t value = 0;  // (prediction + r) mod 2^b
  int symbol = 0;          // the bit width of |r|
  bool negative = false;
  std::uint32_t magnitude = 0;  // |r|; for the decoder, a symbol of b with a magnitude other than
                                // 2^(b-1), or not negative, lies outside the b-bit range
  bool inRange(int b) const { return symbol < b || (magnitude == (1u << (b - 1)) && negative); }
};
template <class Bits>
ContextResidual codeContextResidual(Bits bits, DeltaDecisionModels& m, const ContextPageState::Contexts& ctx,
                                    std::int32_t prediction, std::int32_t value) {
  const int b = m.valueBits();
  const std::int32_t r = predictionDelta(value, prediction, b);
  int negative = r < 0 ? 1 : 0;
  std::uint32_t magnitude = static_cast<std::uint32_t>(r < 0 ? -static_cast<std::int64_t>(r) : r);
  ContextResidual out;
  out.symbol = codeDeltaDecisions(bits, m, ctx.context, ctx.signContext, lead1Symbol(r), negative, magnitude);
  out.negative = negative != 0;
  out.magnitude = out.symbol == 0 ? 0 : magnitude;
  const std::int32_t decoded = out.symbol == 0 ? 0
                               : negative      ? -static_cast<std::int32_t>(magnitude)
                                               : static_cast<std::int32_t>(magnitude);
  out.value = wrapSample(prediction + decoded, b, false);
  return out;
}

// Codes one value with its point's prediction and contexts (the encoder's step).
void encodeContextValue(RangeEncoder& out, ContextPageState& state, std::uint64_t h, const ContextPoint& point,
                        std::int32_t value);

// The bytes of one page: the values of its points inside the volume `dims`, in hierarchical order;
// valueOf(q) gives the value of any point of the volume (the encoder has them all).
template <class ValueOf>
std::string encodeContextPage(const HzOrder& order, const Dims3& dims, int valueBits, int pageBits, std::uint64_t page,
                              ValueOf&& valueOf) {
  ContextPageState state(valueBits, pageBits, page);
  RangeEncoder out;
  order.forEachInside(dims, page << pageBits, (page + 1) << pageBits,
                      [&](std::uint64_t h, const GridPoint& p, int level, int scaleLog2, unsigned oddAxes) {
                        const ContextPoint cp =
                            contextPoint(order, dims, state, h, p, level, scaleLog2, oddAxes, valueOf);
                        encodeContextValue(out, state, h, cp, valueOf(p));
                      });
  return out.finish();
}

// The bytes of one context page (data or gradients, context_gradient_coder.h) as a reader walks
// them: the range decoder, and the page's errors, each a StreamError at the byte offset reached,
// naming the page.
class ContextPageInput {
 public:
  // `streamOffset` is the offset of the page's first byte in the stream and `what` names the page
  // ("data page 17"). The bytes must outlive the input. Throws StreamError for a page shorter than
  // 5 bytes or whose first byte is not 0.
  ContextPageInput(std::string_view bytes, std::size_t streamOffset, std::string what);
  RangeDecoder& decoder() { return in_; }
  // After value `value` (counted from 0) of the page: throws if the decoder read past the page.
  void checkInside(std::uint64_t value) const;
  // After the page's last point, `values` of them: throws for a page of no point, or for bytes left.
  void finish(std::uint64_t values) const;
  [[noreturn]] void fail(const std::string& detail) const;

 private:
  RangeDecoder in_;
  std::size_t pageBytes_, streamOffset_;
  std::string what_;
};

// Reads the values of one page.
class ContextPageReader {
 public:
  // As ContextPageInput's constructor, for a page of values of valueBits bits.
  ContextPageReader(std::string_view bytes, int valueBits, int pageBits, std::uint64_t page, std::size_t streamOffset,
                    std::string what);
  // Decodes the page's points inside the volume in hierarchical order: valueOf(q) gives the value
  // of a corner (coarser than the point, so decoded before it: in an earlier page, or stored in
  // this one), store(h, p, value) takes each value. Returns how many points it decoded. Throws
  // StreamError (above), and after the last point unless the bytes are used up exactly.
  template <class ValueOf, class Store>
  std::uint64_t decode(const HzOrder& order, const Dims3& dims, ValueOf&& valueOf, Store&& store) {
    order.forEachInside(dims, state_.pageBegin(), state_.pageBegin() + (std::uint64_t{1} << pageBits_),
                        [&](std::uint64_t h, const GridPoint& p, int level, int scaleLog2, unsigned oddAxes) {
                          const ContextPoint cp =
                              contextPoint(order, dims, state_, h, p, level, scaleLog2, oddAxes, valueOf);
                          store(h, p, next(h, cp));
                        });
    input_.finish(read_);
    return read_;
  }

 private:
  std::int32_t next(std::uint64_t h, const ContextPoint& point);
  ContextPageState state_;
  ContextPageInput input_;
  int pageBits_;
  std::uint64_t read_ = 0;
};

}  // namespace voxref::ref
