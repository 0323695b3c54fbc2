// The context coder of the gradients (reference/leb/context_gradient_coder.h;
// reference/leb/FORMAT.md, "Context gradient pages"): the sphere's magnitude against a search,
// pages of any int8 vectors back to their vectors, and pages that break the format's rules refused
// with their offset.
#include "reference/leb/context_gradient_coder.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/leb/gradients.h"
#include "reference/leb/leb_grid.h"
#include "reference/leb/range_coder.h"
#include "tests/reference/leb/leb_test_volumes.h"

namespace voxref::ref {
namespace {

// sphereMagnitude is the integer m nearest to sqrt(t), t = 127^2 - gx^2 - gy^2 (0 for t <= 0): found
// here by a search for the m with (2m - 1)^2 <= 4t < (2m + 1)^2, in integers, for every int8 pair.
TEST(ContextGradientCoder, TheSphereMagnitudeIsTheNearestIntegerRoot) {
  for (int gx = -128; gx <= 127; ++gx)
    for (int gy = -128; gy <= 127; ++gy) {
      const int t = 127 * 127 - gx * gx - gy * gy;
      int expected = 0;
      if (t > 0)
        for (int m = 1; m <= 127; ++m)
          if ((2 * m - 1) * (2 * m - 1) <= 4 * t && 4 * t < (2 * m + 1) * (2 * m + 1)) expected = m;
      ASSERT_EQ(sphereMagnitude(gx, gy), expected) << gx << ", " << gy;
    }
}

// A page of gradients of a small volume (all of its points in page 0), decoded with the vectors
// the decoder has made so far as the corners.
class ContextGradientPage : public ::testing::Test {
 protected:
  int linear(const GridPoint& q) const { return (q[2] * dims[1] + q[1]) * dims[0] + q[0]; }
  std::array<std::int8_t, 3> at(const std::vector<std::int8_t>& g, const GridPoint& q) const {
    const auto i = static_cast<std::size_t>(3 * linear(q));
    return {g[i], g[i + 1], g[i + 2]};
  }
  std::string encode(const std::vector<std::int8_t>& g) const {
    return encodeContextGradientPage(order, dims, 12, 0, [&](const GridPoint& q) { return at(g, q); });
  }
  // The vectors decoded from `bytes` into `out`, or the reader's error.
  std::string decode(const std::string& bytes, std::vector<std::int8_t>& out) const {
    out.assign(3 * static_cast<std::size_t>(sampleCount(dims)), 0);
    try {
      ContextGradientPageReader reader(bytes, 12, 0, 1000, "gradients page 0");
      reader.decode(
          order, dims, [&](const GridPoint& q) { return at(out, q); },
          [&](std::uint64_t, const GridPoint& p, const std::array<std::int8_t, 3>& g) {
            for (int a = 0; a < 3; ++a)
              out[static_cast<std::size_t>(3 * linear(p) + a)] = g[static_cast<std::size_t>(a)];
          });
    } catch (const StreamError& e) {
      return e.what();
    }
    return "";
  }
  Dims3 dims{5, 4, 3};
  HzOrder order{lebGridCovering(dims)};
};

// Unit vectors (the gradients of noise and of a smooth field), zero vectors, and any int8 triple
// (off the sphere, -128): every page decodes to its vectors.
TEST_F(ContextGradientPage, AnyVectorsDecodeToThemselves) {
  std::vector<std::vector<std::int8_t>> cases{quantizedGradients(test_support::noise(dims, 8, 5)),
                                              quantizedGradients(test_support::smooth(dims, 8)),
                                              std::vector<std::int8_t>(60 * 3, 0)};
  std::mt19937 rng(9);
  std::vector<std::int8_t> any(60 * 3);
  for (auto& c : any) c = static_cast<std::int8_t>(rng() % 256);
  cases.push_back(any);
  std::vector<std::int8_t> mixed = cases[0];  // some vectors zero, some at -128
  for (std::size_t i = 0; i < mixed.size(); i += 7) mixed[i] = i % 2 ? 0 : -128;
  cases.push_back(mixed);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::vector<std::int8_t> out;
    ASSERT_EQ(decode(encode(cases[i]), out), "") << "case " << i;
    EXPECT_EQ(out, cases[i]) << "case " << i;
  }
}

// A one-point volume's page written decision by decision (reference/leb/FORMAT.md, "Context
// gradient pages"): the page's mode 0 (no repeats), the root corner's contexts (zero context 0, component contexts 0
// and sign context 3, gz's sign context 1) and predictions (128 biased, so 0), gx and gy of 0, gz's sign, then gz's
// residual of magnitude `zMagnitude` (sign `zResidualNegative`) from (sign) sphereMagnitude(0, 0) = 127.
std::string onePointPage(int zNegative, int zSymbol, int zResidualNegative, std::uint32_t zMagnitude) {
  ContextGradientPageState state(4, 0);
  RangeEncoder out;
  EncodeBits bits{out};
  bits.bit(state.modeModel(), 0);  // the page codes every vector in full
  bits.bit(state.zeroModel(0), 0);
  for (int a = 0; a < 2; ++a) {
    int negative = 0;
    std::uint32_t magnitude = 0;
    codeDeltaDecisions(bits, state.componentModels(a), 0, 3, 0, negative, magnitude);
  }
  bits.bit(state.zSignModel(1), zNegative);
  codeDeltaDecisions(bits, state.zModels(), contextRangeBucket(127), 0, zSymbol, zResidualNegative, zMagnitude);
  return out.finish();
}

TEST(ContextGradientCoder, PagesThatBreakTheRulesAreRefusedWithTheirOffset) {
  const Dims3 one{1, 1, 1};
  const HzOrder order(lebGridCovering(one));
  const auto errorOf = [&](const std::string& bytes) -> std::string {
    try {
      ContextGradientPageReader reader(bytes, 4, 0, 500, "gradients page 0");
      reader.decode(
          order, one,
          [](const GridPoint&) {
            return std::array<std::int8_t, 3>{0, 0, 0};
          },
          [](std::uint64_t, const GridPoint&, const std::array<std::int8_t, 3>&) {});
    } catch (const StreamError& e) {
      const std::string what = e.what();
      return what.substr(what.find(": ") + 2);  // the offset depends on the coder's flush
    }
    return "";
  };
  // gz = 127: the one valid coding of (0, 0, 127) decodes.
  EXPECT_EQ(errorOf(onePointPage(0, 0, 0, 0)), "");
  // gz = 127 - 127 = 0 after a sign of +: the zero vector, though its flag said otherwise.
  EXPECT_EQ(errorOf(onePointPage(0, 7, 1, 127)),
            "gradients page 0: gradient 0: (0, 0, 0) coded as a vector that is not zero");
  // gz = (127 + 100) mod 256, read as int8: -29, after a sign of +.
  EXPECT_EQ(errorOf(onePointPage(0, 7, 0, 100)), "gradients page 0: gradient 0: gz is -29, against its coded sign");
  // A residual of +128 (the 8-bit range holds -128 only).
  EXPECT_EQ(errorOf(onePointPage(1, 8, 0, 128)),
            "gradients page 0: gradient 0: a residual of +128 is outside the 8-bit range");
  // The shared page checks: bytes left, a short page.
  const std::string valid = onePointPage(0, 0, 0, 0);
  EXPECT_EQ(errorOf(valid + std::string(2, '\0')), "gradients page 0: 2 bytes left after the last value");
  EXPECT_EQ(errorOf(valid.substr(0, 4)), "gradients page 0: a page of the context coder has at least 5 bytes");
}

// Pages whose vectors repeat, written decision by decision (reference/leb/FORMAT.md, "Context
// gradient pages", steps 2 and 3). The volume 3x1x1 holds two root corners, (0, 0, 0) and (2, 0, 0),
// whose vectors a = (0, 0, 127) and b = (0, 0, -127) are coded in full as onePointPage does, then
// (1, 0, 0), whose corners they are; pages of 2^5 indices hold the whole grid.
class RepeatedVectorPage : public ::testing::Test {
 protected:
  // Writes the two roots' vectors; `third` then writes the third point's decisions, given its
  // prediction and contexts (from the corners a and b).
  template <class Third>
  std::string page(Third&& third) const {
    ContextGradientPageState state(5, 0);
    RangeEncoder out;
    EncodeBits bits{out};
    bits.bit(state.modeModel(), 1);  // the page takes steps 2 and 3
    int point = 0;
    order.forEachInside(dims, 0, 32, [&](std::uint64_t h, const GridPoint& p, int level, int s, unsigned odd) {
      if (point++ < 2) {  // a root corner: zero context 0, components' contexts 0 and 3, gz's sign context 1
        bits.bit(state.zeroModel(0), 0);
        if (point == 2) bits.bit(state.recentModel(0), 0);  // b is not a recent vector
        for (int a = 0; a < 2; ++a) {
          int negative = 0;
          std::uint32_t magnitude = 0;
          codeDeltaDecisions(bits, state.componentModels(a), 0, 3, 0, negative, magnitude);
        }
        bits.bit(state.zSignModel(1), point == 2 ? 1 : 0);
        int negative = 0;
        std::uint32_t magnitude = 0;
        codeDeltaDecisions(bits, state.zModels(), contextRangeBucket(127), 0, 0, negative, magnitude);
        state.recentVectors().use(gradientKey({0, 0, static_cast<std::int8_t>(point == 2 ? -127 : 127)}));
        return;
      }
      const GradientPoint g = gradientPoint(order, dims, state, h, p, level, s, odd, [&](const GridPoint& q) {
        return std::array<std::int8_t, 3>{0, 0, static_cast<std::int8_t>(q[0] == 0 ? 127 : -127)};
      });
      third(bits, state, g);
    });
    return out.finish();
  }
  std::string errorOf(const std::string& bytes) const {
    std::vector<std::array<std::int8_t, 3>> got;
    try {
      ContextGradientPageReader reader(bytes, 5, 0, 500, "gradients page 0");
      reader.decode(
          order, dims,
          [&](const GridPoint& q) {
            return std::array<std::int8_t, 3>{0, 0, static_cast<std::int8_t>(q[0] == 0 ? 127 : -127)};
          },
          [&](std::uint64_t, const GridPoint&, const std::array<std::int8_t, 3>& v) { got.push_back(v); });
    } catch (const StreamError& e) {
      const std::string what = e.what();
      return what.substr(what.find(": ") + 2);
    }
    std::ostringstream text;
    for (const auto& v : got) text << '(' << int{v[0]} << ' ' << int{v[1]} << ' ' << int{v[2]} << ')';
    return text.str();
  }
  Dims3 dims{3, 1, 1};
  HzOrder order{lebGridCovering(dims)};
};

TEST_F(RepeatedVectorPage, ACornersVectorAndARecentOneDecodeAndTheirMisusesAreRefused) {
  // The corners' vectors a and b, in the corners' order; the recent ones b (rank 0), a (rank 1).
  const auto corner = [](std::uint32_t index) {
    return [index](EncodeBits& bits, ContextGradientPageState& state, const GradientPoint& g) {
      ASSERT_EQ(g.corners.vectorCount, 2);
      bits.bit(state.zeroModel(g.contexts.zero), 0);
      bits.bit(state.cornerModel(1), 1);
      bits.direct(index, 1);
    };
  };
  EXPECT_EQ(errorOf(page(corner(0))), "(0 0 127)(0 0 -127)(0 0 127)");
  EXPECT_EQ(errorOf(page(corner(1))), "(0 0 127)(0 0 -127)(0 0 -127)");
  // Not a corner's vector, then a recent one: both recent vectors are corners' vectors.
  const auto recent = [](std::uint32_t rank) {
    return [rank](EncodeBits& bits, ContextGradientPageState& state, const GradientPoint& g) {
      bits.bit(state.zeroModel(g.contexts.zero), 0);
      bits.bit(state.cornerModel(1), 0);
      bits.bit(state.recentModel(1), 1);
      // The rank's q = rank + 1 by its width down the tree, then the bits below its leading one.
      const std::uint32_t q = rank + 1, w = static_cast<std::uint32_t>(std::bit_width(q));
      int node = 1;
      for (int level = 4; level >= 0; --level)
        node = 2 * node + bits.bit(state.rankModel(1, node), ((w - 1) >> level) & 1);
      bits.direct(q & ((1u << (w - 1)) - 1), static_cast<int>(w - 1));
    };
  };
  EXPECT_EQ(errorOf(page(recent(1))), "gradients page 0: gradient 2: a corner's vector coded as a recent one");
  EXPECT_EQ(errorOf(page(recent(2))), "gradients page 0: gradient 2: a recent vector's rank past the page's 2 vectors");
  // Not a corner's vector, not a recent one, then a in full: a repeat coded in full.
  EXPECT_EQ(errorOf(page([](EncodeBits& bits, ContextGradientPageState& state, const GradientPoint& g) {
              bits.bit(state.zeroModel(g.contexts.zero), 0);
              bits.bit(state.cornerModel(1), 0);
              bits.bit(state.recentModel(1), 0);
              for (int a = 0; a < 2; ++a) {
                int negative = 0;
                std::uint32_t magnitude = 0;
                codeDeltaDecisions(bits, state.componentModels(a), g.contexts.component[a].context,
                                   g.contexts.component[a].signContext, 0, negative, magnitude);
              }
              bits.bit(state.zSignModel(g.contexts.zSign), 0);
              int negative = 0;
              std::uint32_t magnitude = 0;
              codeDeltaDecisions(bits, state.zModels(), contextRangeBucket(127), 0, 0, negative, magnitude);
            })),
            "gradients page 0: gradient 2: a corner's or a recent vector coded in full");
}

}  // namespace
}  // namespace voxref::ref
