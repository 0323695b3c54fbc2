// voxref's context coder of an LEB stream's gradients (FORMAT.md beside this file, "Context
// gradient pages", version 4; issue 18, goal 5: the gradients beyond zstd -19 while keeping page
// random access).
//
// A stored gradient is a unit vector quantized to snorm8 (gradients.h): (gx, gy, gz) with
// gx^2 + gy^2 + gz^2 close to 127^2, or (0, 0, 0). A coder of the three components on their own
// spends on gz what gx and gy already say: given them, |gz| is sqrt(127^2 - gx^2 - gy^2) to within
// the rounding. This coder codes, for each point, in one function for the encoder and the decoder
// (codeContextGradient):
//   1. whether the vector is (0, 0, 0), with contexts from its corners' and its neighbours' vectors;
//   2. whether it is one of its corners' vectors, and which;
//   3. else whether it is one of the page's recent vectors, and its rank among them (central
//      differences of 8-bit samples take few distinct directions, so vectors repeat exactly: the
//      repeats that gave zstd -19 its lead);
//   4. else gx and gy as the context coder of the samples codes a value (context_value_coder.h):
//      each predicted from its corners' components, its residual's decisions with contexts from
//      their range and from the neighbours' residuals of the same component;
//   5. the sign of gz, with the sign of its corners' mean gz as context;
//   6. gz's residual from (sign) sphereMagnitude(gx, gy), with the magnitude's bucket as context.
// Steps 2 and 3 are taken in pages whose first decision, the mode, says so; the encoder codes each
// page both ways and keeps the shorter.
// The corners and the neighbours are those of the samples' context coder, so a gradient page
// decodes given its points' corners' gradients, coarser points in coarser pages, as a data page
// does with the samples; nothing of it depends on the data channel.
//
// The decoder is for untrusted bytes: besides ContextPageInput's checks, a page that codes a
// vector flagged non-zero as (0, 0, 0), a gz whose sign is not the coded one, a residual of +128,
// a corner's place or a rank past the end, a corner's vector as a recent one, or a repeat in full
// throws StreamError with the byte offset and the page's name. So every vector has one coding.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "reference/leb/context_value_coder.h"
#include "reference/leb/recent_vectors.h"

namespace voxref::ref {

// The nearest integer to sqrt(max(0, 127^2 - gx^2 - gy^2)) (never a tie: the square root of an
// integer is not m + 1/2), in integers: |gz| of a unit vector with components gx / 127 and gy / 127.
int sphereMagnitude(int gx, int gy);

// A component's value as the coder predicts it: gx + 128, in 0..255, so that the samples' rules
// (unsigned 8-bit values) apply unchanged.
inline std::int32_t biasedComponent(std::int8_t g) { return static_cast<std::int32_t>(g) + 128; }

// A vector as one number (gx, gy and gz as bytes, gx lowest), and back.
inline std::uint32_t gradientKey(const std::array<std::int8_t, 3>& g) {
  return static_cast<std::uint8_t>(g[0]) | (std::uint32_t{static_cast<std::uint8_t>(g[1])} << 8) |
         (std::uint32_t{static_cast<std::uint8_t>(g[2])} << 16);
}
inline std::array<std::int8_t, 3> gradientOfKey(std::uint32_t key) {
  return {static_cast<std::int8_t>(key & 0xff), static_cast<std::int8_t>((key >> 8) & 0xff),
          static_cast<std::int8_t>((key >> 16) & 0xff)};
}

inline constexpr int kGradientZeroContexts = 12;                         // corners' zero vectors (3) x neighbours' (4)
inline constexpr int kGradientSignContexts = 3;                          // the corners' mean gz: negative, 0, positive
inline constexpr int kGradientMagnitudeContexts = kContextRangeBuckets;  // contextRangeBucket(magnitude)

// A point's corners, for its gradient: per component, the prediction (of the biased component)
// and the range's bucket, as cornerPrediction gives them; how many corners are (0, 0, 0):
// zeroCorners 0 for none, 1 for some, 2 for all; and their distinct vectors other than (0, 0, 0),
// in the corners' order (forEachCornerInside), the first of each kept. A root corner's: predictions
// 128, buckets 0, 0, no vectors.
struct GradientCorners {
  std::array<CornerPrediction, 3> component{{{128, 0}, {128, 0}, {128, 0}}};
  int zeroCorners = 0;
  std::array<std::array<std::int8_t, 3>, 8> vectors{};
  int vectorCount = 0;
  // The place of g among `vectors`, or -1.
  int find(const std::array<std::int8_t, 3>& g) const {
    for (int i = 0; i < vectorCount; ++i)
      if (vectors[static_cast<std::size_t>(i)] == g) return i;
    return -1;
  }
};
// vectorOf(q) gives a corner's gradient, std::array<std::int8_t, 3>.
template <class VectorOf>
GradientCorners gradientCorners(const GridPoint& p, int scaleLog2, unsigned oddAxes, const Dims3& dims,
                                VectorOf&& vectorOf) {
  GradientCorners c;
  std::array<std::int64_t, 3> sum{0, 0, 0};
  std::array<std::int32_t, 3> lo{0, 0, 0}, hi{0, 0, 0};
  int zeros = 0;
  bool first = true;
  const int m = forEachCornerInside(p, scaleLog2, oddAxes, dims, [&](const GridPoint& q) {
    const std::array<std::int8_t, 3> g = vectorOf(q);
    const bool zero = g[0] == 0 && g[1] == 0 && g[2] == 0;
    zeros += zero;
    if (!zero && c.find(g) < 0) c.vectors[static_cast<std::size_t>(c.vectorCount++)] = g;
    for (std::size_t a = 0; a < 3; ++a) {
      const std::int32_t v = biasedComponent(g[a]);
      sum[a] += v;
      lo[a] = first ? v : std::min(lo[a], v);
      hi[a] = first ? v : std::max(hi[a], v);
    }
    first = false;
  });
  for (std::size_t a = 0; a < 3; ++a) c.component[a] = cornerMean(sum[a], lo[a], hi[a], m);
  c.zeroCorners = zeros == 0 ? 0 : zeros == m ? 2 : 1;
  return c;
}

// What one gradient page's coding keeps between its points: its models, and for every point coded
// so far, by its place in the page, whether its vector was (0, 0, 0) and gx's and gy's residual
// symbols and signs (for the neighbours' contexts).
class ContextGradientPageState {
 public:
  ContextGradientPageState(int pageBits, std::uint64_t page);
  std::uint64_t pageBegin() const { return begin_; }
  struct Contexts {
    int zero = 0;
    std::array<ContextPageState::Contexts, 2> component;  // gx, gy: as the samples' contexts
    int zSign = 1;
    int magnitude = 0;  // filled by codeContextGradient once gx and gy are known
  };
  // The contexts of p (index h, class c, not a root corner) with corners `corners`: its neighbours
  // (ContextPageState::contexts) count with what was recorded for them.
  Contexts contexts(const HzOrder& order, std::uint64_t h, const GridPoint& p, const LebPointClass& c,
                    const GradientCorners& corners) const;
  void recordZero(std::uint64_t h);
  void record(std::uint64_t h, const std::array<int, 2>& symbol, const std::array<bool, 2>& negative);

  // The page's first decision (FORMAT.md, "Context gradient pages"): 1 when its points take steps 2
  // and 3 (the repeats), 0 when every non-zero vector is coded in full.
  BitModel& modeModel() { return mode_; }
  bool repeats = true;
  BitModel& zeroModel(int context) { return zero_[static_cast<std::size_t>(context)]; }
  // Steps 2 and 3 of "Context gradient pages": a corner's vector (context: one corner vector or
  // more, and whether a corner is (0, 0, 0)), one of the page's recent vectors (context: whether
  // the point has corner vectors, and whether a corner is (0, 0, 0)), and the recent vector's rank's
  // bit width, down a tree (node 1 at the root) per whether the point has corner vectors.
  BitModel& cornerModel(int context) { return corner_[static_cast<std::size_t>(context)]; }
  BitModel& recentModel(int context) { return recent_[static_cast<std::size_t>(context)]; }
  BitModel& rankModel(int context, int node) { return rank_[static_cast<std::size_t>(context) * 32 + node]; }
  // The page's non-zero vectors coded so far, most recent first.
  RecentVectors& recentVectors() { return recentVectors_; }
  BitModel& zSignModel(int context) { return zSign_[static_cast<std::size_t>(context)]; }
  DeltaDecisionModels& componentModels(int axis) { return xy_[static_cast<std::size_t>(axis)]; }
  DeltaDecisionModels& zModels() { return z_; }

 private:
  std::array<DeltaDecisionModels, 2> xy_;
  DeltaDecisionModels z_;
  std::vector<BitModel> zero_, zSign_;
  BitModel mode_{};
  std::array<BitModel, 4> corner_{}, recent_{};
  std::array<BitModel, 64> rank_{};
  RecentVectors recentVectors_;
  std::uint64_t begin_;
  // By place in the page: 1 for a (0, 0, 0) vector; gx's and gy's symbols, negated when negative.
  std::vector<std::uint8_t> zeroVector_;
  std::array<std::vector<std::int8_t>, 2> signedSymbol_;
};

// A point's prediction and contexts.
struct GradientPoint {
  GradientCorners corners;
  ContextGradientPageState::Contexts contexts;
};
template <class VectorOf>
GradientPoint gradientPoint(const HzOrder& order, const Dims3& dims, const ContextGradientPageState& state,
                            std::uint64_t h, const GridPoint& p, int level, int scaleLog2, unsigned oddAxes,
                            VectorOf&& vectorOf) {
  if (level < 0) return {};  // a root corner: no corners, no neighbours
  GradientPoint g;
  g.corners = gradientCorners(p, scaleLog2, oddAxes, dims, vectorOf);
  g.contexts =
      state.contexts(order, h, p, LebPointClass{level, scaleLog2, std::popcount(oddAxes) - 1, oddAxes}, g.corners);
  return g;
}

// Codes one gradient (the encoder's step).
void encodeContextGradient(RangeEncoder& out, ContextGradientPageState& state, std::uint64_t h,
                           const GradientPoint& point, const std::array<std::int8_t, 3>& g);

// The bytes of one gradient page: the gradients of its points inside the volume `dims`, in
// hierarchical order; vectorOf(q) gives any point's gradient (the encoder has them all). The page
// is coded with the repeats and without them, and the shorter kept (the one without on a tie): the
// repeats pay on vectors that take few directions (central differences), and cost on smooth ones
// (diffused gradients), whose repeats the prediction codes for less.
template <class VectorOf>
std::string encodeContextGradientPage(const HzOrder& order, const Dims3& dims, int pageBits, std::uint64_t page,
                                      VectorOf&& vectorOf) {
  const auto coded = [&](bool repeats) {
    ContextGradientPageState state(pageBits, page);
    RangeEncoder out;
    EncodeBits{out}.bit(state.modeModel(), repeats ? 1 : 0);
    state.repeats = repeats;
    order.forEachInside(
        dims, page << pageBits, (page + 1) << pageBits,
        [&](std::uint64_t h, const GridPoint& p, int level, int scaleLog2, unsigned oddAxes) {
          encodeContextGradient(
              out, state, h, gradientPoint(order, dims, state, h, p, level, scaleLog2, oddAxes, vectorOf), vectorOf(p));
        });
    return out.finish();
  };
  std::string without = coded(false), with = coded(true);
  return with.size() < without.size() ? with : without;
}

// Reads the gradients of one page (the constructor's checks: ContextPageInput's).
class ContextGradientPageReader {
 public:
  ContextGradientPageReader(std::string_view bytes, int pageBits, std::uint64_t page, std::size_t streamOffset,
                            std::string what);
  // As ContextPageReader::decode, with vectorOf(q) giving a corner's gradient and store(h, p, g)
  // taking each gradient (std::array<std::int8_t, 3>).
  template <class VectorOf, class Store>
  std::uint64_t decode(const HzOrder& order, const Dims3& dims, VectorOf&& vectorOf, Store&& store) {
    state_.repeats = input_.decoder().decode(state_.modeModel()) == 1;
    order.forEachInside(dims, state_.pageBegin(), state_.pageBegin() + (std::uint64_t{1} << pageBits_),
                        [&](std::uint64_t h, const GridPoint& p, int level, int scaleLog2, unsigned oddAxes) {
                          store(h, p,
                                next(h, gradientPoint(order, dims, state_, h, p, level, scaleLog2, oddAxes, vectorOf)));
                        });
    input_.finish(read_);
    return read_;
  }

 private:
  std::array<std::int8_t, 3> next(std::uint64_t h, const GradientPoint& point);
  ContextGradientPageState state_;
  ContextPageInput input_;
  int pageBits_;
  std::uint64_t read_ = 0;
};

}  // namespace voxref::ref
