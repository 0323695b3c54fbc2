#include "reference/leb/context_gradient_coder.h"

#include <bit>
#include <cmath>
#include <optional>

#include "reference/common/byte_stream.h"
#include "reference/leb/prediction.h"

namespace voxref::ref {

int sphereMagnitude(int gx, int gy) {
  const int t = 127 * 127 - gx * gx - gy * gy;
  if (t <= 0) return 0;
  // The integer square root m (m^2 <= t < (m + 1)^2), from the double root corrected by integers;
  // then sqrt(t) > m + 1/2 exactly when t > m^2 + m (t and m are integers).
  int m = static_cast<int>(std::sqrt(static_cast<double>(t)));
  while (m * m > t) --m;
  while ((m + 1) * (m + 1) <= t) ++m;
  return t > m * m + m ? m + 1 : m;
}

ContextGradientPageState::ContextGradientPageState(int pageBits, std::uint64_t page)
    : xy_{DeltaDecisionModels(8, kContextContexts, kContextSignContexts),
          DeltaDecisionModels(8, kContextContexts, kContextSignContexts)},
      z_(8, kGradientMagnitudeContexts, 1),
      zero_(kGradientZeroContexts),
      zSign_(kGradientSignContexts),
      recentVectors_(std::size_t{1} << pageBits),
      begin_(page << pageBits),
      zeroVector_(std::size_t{1} << pageBits, 0),
      signedSymbol_{std::vector<std::int8_t>(std::size_t{1} << pageBits, 0),
                    std::vector<std::int8_t>(std::size_t{1} << pageBits, 0)} {}

ContextGradientPageState::Contexts ContextGradientPageState::contexts(const HzOrder& order, std::uint64_t h,
                                                                      const GridPoint& p, const LebPointClass& c,
                                                                      const GradientCorners& corners) const {
  // FORMAT.md, "Context gradient pages": the neighbours of "Context pages", p's own class at -2h on
  // each axis, counted when they lie in p's page.
  std::uint64_t below[3];
  order.indicesBelow(h, p, c, below);
  int zeros = 0;
  std::array<int, 2> symbols{0, 0}, signs{0, 0};
  for (const std::uint64_t hq : below) {
    if (hq == HzOrder::kNoIndex || hq < begin_ || hq - begin_ >= zeroVector_.size()) continue;
    const auto at = static_cast<std::size_t>(hq - begin_);
    zeros += zeroVector_[at];
    for (std::size_t a = 0; a < 2; ++a) {
      const int s = signedSymbol_[a][at];
      symbols[a] += s < 0 ? -s : s;
      signs[a] += (s > 0) - (s < 0);
    }
  }
  Contexts x;
  x.zero = 4 * corners.zeroCorners + zeros;
  for (std::size_t a = 0; a < 2; ++a)
    x.component[a] = {
        std::min(symbols[a], kContextNeighbourSums - 1) * kContextRangeBuckets + corners.component[a].rangeBucket,
        std::clamp(signs[a], -3, 3) + 3};
  const std::int32_t zMean = corners.component[2].prediction;
  x.zSign = zMean < 128 ? 0 : zMean == 128 ? 1 : 2;
  return x;
}

void ContextGradientPageState::recordZero(std::uint64_t h) { zeroVector_[static_cast<std::size_t>(h - begin_)] = 1; }

void ContextGradientPageState::record(std::uint64_t h, const std::array<int, 2>& symbol,
                                      const std::array<bool, 2>& negative) {
  const auto at = static_cast<std::size_t>(h - begin_);
  for (std::size_t a = 0; a < 2; ++a)
    signedSymbol_[a][at] = static_cast<std::int8_t>(negative[a] ? -symbol[a] : symbol[a]);
}

namespace {

// What decoding a vector found wrong (the encoder never makes one): the decoder's message.
enum class GradientProblem {
  None,
  ResidualRange,
  ZeroFlagged,
  SignMismatch,
  CornerIndex,     // a corner's vector past the corners' vectors
  RankRange,       // a recent vector past the page's
  CornerAsRecent,  // a corner's vector coded as a recent one
  RepeatInFull     // a corner's or a recent vector coded in full
};

// Records a repeated vector's gx and gy residuals for the neighbours' contexts, as coding it in
// full would have (the same symbols and signs).
void recordRepeat(ContextGradientPageState& state, std::uint64_t h, const GradientPoint& point,
                  const std::array<std::int8_t, 3>& g) {
  std::array<int, 2> symbol{0, 0};
  std::array<bool, 2> negative{false, false};
  for (std::size_t a = 0; a < 2; ++a) {
    const std::int32_t r = predictionDelta(biasedComponent(g[a]), point.corners.component[a].prediction, 8);
    symbol[a] = lead1Symbol(r);
    negative[a] = r < 0;
  }
  state.record(h, symbol, negative);
}

// FORMAT.md, "Context gradient pages": one vector's decisions, in one function for the encoder
// (EncodeBits: g is the vector, and stays) and the decoder (DecodeBits: g is set). Records what the
// neighbours' contexts need.
template <class Bits>
GradientProblem codeContextGradient(Bits bits, ContextGradientPageState& state, std::uint64_t h,
                                    const GradientPoint& point, std::array<std::int8_t, 3>& g) {
  const ContextGradientPageState::Contexts& ctx = point.contexts;
  // 1. The zero vector.
  const int isZero = g[0] == 0 && g[1] == 0 && g[2] == 0;
  if (bits.bit(state.zeroModel(ctx.zero), isZero) == 1) {
    g = {0, 0, 0};
    state.recordZero(h);
    return GradientProblem::None;
  }
  const GradientCorners& corners = point.corners;
  RecentVectors& recent = state.recentVectors();
  const auto repeat = [&](const std::array<std::int8_t, 3>& v) {
    g = v;
    recordRepeat(state, h, point, g);
    recent.use(gradientKey(g));
    return GradientProblem::None;
  };
  // 2. One of the corners' vectors, by its place among them.
  const int cornerAt = corners.find(g);  // the encoder's; the decoder's g is (0, 0, 0), never a corner's
  if (state.repeats && corners.vectorCount > 0 &&
      bits.bit(state.cornerModel((corners.vectorCount > 1 ? 1 : 0) + (corners.zeroCorners > 0 ? 2 : 0)),
               cornerAt >= 0 ? 1 : 0) == 1) {
    const auto i = bits.direct(static_cast<std::uint32_t>(cornerAt >= 0 ? cornerAt : 0),
                               static_cast<int>(std::bit_width(static_cast<unsigned>(corners.vectorCount - 1))));
    if (i >= static_cast<std::uint32_t>(corners.vectorCount)) return GradientProblem::CornerIndex;
    return repeat(corners.vectors[i]);
  }
  // 3. One of the page's recent vectors, by its rank.
  if (state.repeats && recent.size() > 0) {
    const std::optional<std::uint32_t> rank = recent.rankOf(gradientKey(g));  // the encoder's
    const int context = corners.vectorCount > 0 ? 1 : 0;
    if (bits.bit(state.recentModel(context + (corners.zeroCorners > 0 ? 2 : 0)), rank ? 1 : 0) == 1) {
      // The rank r as r + 1 by its bit width, five levels of models per context.
      const std::uint64_t r = codeByBitWidth(
                                  bits, [&](int node) -> BitModel& { return state.rankModel(context, node); }, 5,
                                  std::uint64_t{rank.value_or(0)} + 1) -
                              1;
      if (r >= recent.size()) return GradientProblem::RankRange;
      const std::array<std::int8_t, 3> v = gradientOfKey(recent.at(static_cast<std::uint32_t>(r)));
      if (corners.find(v) >= 0) return GradientProblem::CornerAsRecent;
      return repeat(v);
    }
  }
  // 4. gx and gy, each from its corners' mean, as the samples are coded; 5. gz's sign, 6. gz from
  // the sphere.
  bool inRange = true;
  std::array<int, 2> symbol{0, 0};
  std::array<bool, 2> negative{false, false};
  for (std::size_t a = 0; a < 2; ++a) {
    const ContextResidual r = codeContextResidual(bits, state.componentModels(static_cast<int>(a)), ctx.component[a],
                                                  point.corners.component[a].prediction, biasedComponent(g[a]));
    g[a] = static_cast<std::int8_t>(r.value - 128);
    symbol[a] = r.symbol;
    negative[a] = r.negative;
    inRange = inRange && r.inRange(8);
  }
  state.record(h, symbol, negative);
  const int magnitude = sphereMagnitude(g[0], g[1]);
  const int zNegative = bits.bit(state.zSignModel(ctx.zSign), g[2] < 0 ? 1 : 0);
  const ContextResidual z = codeContextResidual(bits, state.zModels(), {contextRangeBucket(magnitude), 0},
                                                (zNegative ? -magnitude : magnitude) + 128, biasedComponent(g[2]));
  g[2] = static_cast<std::int8_t>(z.value - 128);
  if (!inRange || !z.inRange(8)) return GradientProblem::ResidualRange;
  if ((g[2] < 0) != (zNegative != 0)) return GradientProblem::SignMismatch;
  if (g[0] == 0 && g[1] == 0 && g[2] == 0) return GradientProblem::ZeroFlagged;
  if (state.repeats) {
    if (corners.find(g) >= 0 || recent.rankOf(gradientKey(g))) return GradientProblem::RepeatInFull;
    recent.use(gradientKey(g));
  }
  return GradientProblem::None;
}

}  // namespace

void encodeContextGradient(RangeEncoder& out, ContextGradientPageState& state, std::uint64_t h,
                           const GradientPoint& point, const std::array<std::int8_t, 3>& g) {
  std::array<std::int8_t, 3> v = g;
  codeContextGradient(EncodeBits{out}, state, h, point, v);
}

ContextGradientPageReader::ContextGradientPageReader(std::string_view bytes, int pageBits, std::uint64_t page,
                                                     std::size_t streamOffset, std::string what)
    : state_(pageBits, page), input_(bytes, streamOffset, std::move(what)), pageBits_(pageBits) {}

std::array<std::int8_t, 3> ContextGradientPageReader::next(std::uint64_t h, const GradientPoint& point) {
  std::array<std::int8_t, 3> g{0, 0, 0};
  const GradientProblem problem = codeContextGradient(DecodeBits{input_.decoder()}, state_, h, point, g);
  input_.checkInside(read_);
  const std::string at = "gradient " + std::to_string(read_) + ": ";
  switch (problem) {
    case GradientProblem::None:
      break;
    case GradientProblem::ResidualRange:
      input_.fail(at + "a residual of +128 is outside the 8-bit range");
    case GradientProblem::SignMismatch:
      input_.fail(at + "gz is " + std::to_string(g[2]) + ", against its coded sign");
    case GradientProblem::ZeroFlagged:
      input_.fail(at + "(0, 0, 0) coded as a vector that is not zero");
    case GradientProblem::CornerIndex:
      input_.fail(at + "a corner's vector past the point's " + std::to_string(point.corners.vectorCount));
    case GradientProblem::RankRange:
      input_.fail(at + "a recent vector's rank past the page's " + std::to_string(state_.recentVectors().size()) +
                  " vectors");
    case GradientProblem::CornerAsRecent:
      input_.fail(at + "a corner's vector coded as a recent one");
    case GradientProblem::RepeatInFull:
      input_.fail(at + "a corner's or a recent vector coded in full");
  }
  ++read_;
  return g;
}

}  // namespace voxref::ref
