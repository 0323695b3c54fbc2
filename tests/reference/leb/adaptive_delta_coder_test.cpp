// The adaptive delta coder: pages round-trip bit for bit; its cost at the two extremes follows
// from the model's update rule (a page of zeros) and from counting (random bytes cannot shrink);
// untrusted pages give StreamError, never a wrong count of bytes.
#include "reference/leb/adaptive_delta_coder.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "reference/common/byte_stream.h"

namespace voxref::ref {
namespace {

std::vector<std::int32_t> decodeAll(const std::string& page, std::size_t n, int bits, int components) {
  AdaptivePageReader r(page, bits, components, 0, "page");
  std::vector<std::int32_t> out(n);
  r.read(out);
  r.finish();
  return out;
}

TEST(AdaptiveDeltaCoder, PagesRoundTripForEveryShapeAndTheExtremes) {
  std::mt19937 rng(7);
  for (const int bits : {8, 16})
    for (const int components : {1, 3})
      for (const std::size_t n : {std::size_t{1}, std::size_t{3}, std::size_t{300}, std::size_t{4096}}) {
        const std::int32_t lo = -(1 << (bits - 1)), hi = (1 << (bits - 1)) - 1;
        std::vector<std::int32_t> d(n);
        // Mostly small deltas (what prediction gives), some of every width, both extremes.
        std::geometric_distribution<int> width(0.3);
        for (std::size_t i = 0; i < n; ++i) {
          const int w = std::min(width(rng), bits - 1);
          const std::int32_t m = static_cast<std::int32_t>(rng() & ((1u << w) - 1));
          d[i] = (rng() & 1) ? -m : m;
        }
        d[0] = lo;
        if (n > 1) d[n - 1] = hi;
        const std::string page = encodeAdaptivePage(d, bits, components);
        EXPECT_EQ(decodeAll(page, n, bits, components), d) << bits << " bits, " << components << " components, " << n;
      }
}

// The cost of n zeros. The zero flag of context 0 starts at P(0) = 2^15 / 2^16 and its k-th update
// adds (2^16 - p) >> min(k, 7) (range_coder.h); an ideal coder spends sum -log2 P(0) bits on them.
// The range coder adds its 5 bytes of flush, one byte of rounding, and what truncating the range
// to its top 16 bits before the multiplication loses: at most 2^-8 of the range per decision,
// under 0.0057 bits. (The lead-1 code spends at least one bit per delta: 512 bytes.)
TEST(AdaptiveDeltaCoder, APageOfZerosCostsWhatTheUpdateRuleAllows) {
  const std::size_t n = 4096;
  std::int64_t p0 = 1 << 15;
  double bits = 0.0;
  for (std::size_t k = 1; k <= n; ++k) {
    bits += -std::log2(static_cast<double>(p0) / 65536.0);
    p0 += (65536 - p0) >> std::min<std::size_t>(k, 7);
  }
  const std::string page = encodeAdaptivePage(std::vector<std::int32_t>(n, 0), 8, 1);
  EXPECT_LE(static_cast<double>(page.size()), std::ceil((bits + 0.0057 * static_cast<double>(n)) / 8.0) + 1 + 5)
      << "ideal " << bits << " bits";
  EXPECT_LT(page.size(), 24u);
  EXPECT_EQ(decodeAll(page, n, 8, 1), std::vector<std::int32_t>(n, 0));
}

// Uniformly random 8-bit deltas carry 8 bits each: no lossless coder makes them shorter (bar a
// chance of 2^-64 for 8 bytes), and an adaptive one should not make them much longer.
TEST(AdaptiveDeltaCoder, RandomBytesNeitherShrinkNorGrowMuch) {
  std::mt19937 rng(11);
  std::vector<std::int32_t> d(4096);
  for (auto& v : d) v = static_cast<std::int32_t>(rng() % 256) - 128;
  const std::string page = encodeAdaptivePage(d, 8, 1);
  EXPECT_GE(page.size(), d.size() - 8);
  EXPECT_LE(page.size(), d.size() * 105 / 100);
  EXPECT_EQ(decodeAll(page, d.size(), 8, 1), d);
}

TEST(AdaptiveDeltaCoder, TheEncoderRefusesDeltasOutOfRangeAndOtherShapes) {
  EXPECT_THROW(encodeAdaptivePage(std::vector<std::int32_t>{128}, 8, 1), std::invalid_argument);
  EXPECT_THROW(encodeAdaptivePage(std::vector<std::int32_t>{-129}, 8, 1), std::invalid_argument);
  EXPECT_THROW(encodeAdaptivePage(std::vector<std::int32_t>{1 << 15}, 16, 1), std::invalid_argument);
  EXPECT_THROW(encodeAdaptivePage(std::vector<std::int32_t>{0}, 12, 1), std::invalid_argument);
  EXPECT_THROW(encodeAdaptivePage(std::vector<std::int32_t>{0}, 8, 2), std::invalid_argument);
}

TEST(AdaptiveDeltaCoder, CorruptPagesGiveStreamErrorsNamingThePage) {
  std::vector<std::int32_t> d(500);
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = static_cast<std::int32_t>(i % 7) - 3;
  const std::string page = encodeAdaptivePage(d, 8, 3);
  // The first byte is the encoder's initial cache: always 0.
  std::string bad = page;
  bad[0] = 1;
  EXPECT_THROW(AdaptivePageReader(bad, 8, 3, 100, "gradients page 4"), StreamError);
  const std::string four = page.substr(0, 4);
  EXPECT_THROW(AdaptivePageReader(four, 8, 3, 100, "gradients page 4"), StreamError);
  // Cut short: reading all values runs past the end.
  try {
    const std::string half = page.substr(0, page.size() / 2);
    AdaptivePageReader r(half, 8, 3, 100, "gradients page 4");
    std::vector<std::int32_t> out(d.size());
    r.read(out);
    ADD_FAILURE() << "a page cut in half decoded";
  } catch (const StreamError& e) {
    EXPECT_NE(std::string(e.what()).find("gradients page 4: the page ends inside value"), std::string::npos)
        << e.what();
    EXPECT_GE(e.offset(), 100u);
    EXPECT_LE(e.offset(), 100 + page.size() / 2);
  }
  // Bytes left over after the last value.
  EXPECT_THROW(decodeAll(page + std::string(3, '\0'), d.size(), 8, 3), StreamError);
  // Fewer values read than the page holds leave bytes over too.
  EXPECT_THROW(decodeAll(page, d.size() / 2, 8, 3), StreamError);
}

// Any bytes decode to values in range or throw StreamError; a page the reader accepts whole
// re-encodes to a page that decodes to the same values.
TEST(AdaptiveDeltaCoder, ArbitraryBytesDecodeInRangeOrThrow) {
  std::mt19937 rng(3);
  int accepted = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string bytes(5 + rng() % 40, '\0');
    for (std::size_t i = 1; i < bytes.size(); ++i) bytes[i] = static_cast<char>(rng());
    const int bits = (trial & 1) ? 16 : 8, components = (trial & 2) ? 3 : 1;
    const std::size_t n = 1 + rng() % 64;
    try {
      AdaptivePageReader r(bytes, bits, components, 0, "page");
      std::vector<std::int32_t> out(n);
      r.read(out);
      for (const std::int32_t v : out) {
        ASSERT_GE(v, -(1 << (bits - 1)));
        ASSERT_LT(v, 1 << (bits - 1));
      }
      r.finish();
      ++accepted;
      EXPECT_EQ(decodeAll(encodeAdaptivePage(out, bits, components), n, bits, components), out);
    } catch (const StreamError&) {
    }
  }
  EXPECT_LT(accepted, 2000);
}

}  // namespace
}  // namespace voxref::ref
