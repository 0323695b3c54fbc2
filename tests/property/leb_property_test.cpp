// Properties of the LEB codec's pieces (reference/leb), each against an independent model:
//   prediction.h   predictMidpoint is floor((a + b) / 2) (exact floor division); the delta is a
//                  b-bit two's complement value and reconstruction inverts it, for every width
//   huffman.h      package-merge lengths: within the limit, Kraft sum exactly 1 (2 or more used
//                  symbols; an optimal code is complete), one used symbol gets length 1, and the
//                  total cost equals an unlimited Huffman code's (priority queue) whenever that
//                  code fits the limit, never below it otherwise; canonical codes are prefix-free
//                  (pairwise check) and the one-lookup table decodes every code under any suffix
//   lead1_coder.h  random delta pages (context restarts per page) decode to the same deltas
//   leb_codec.h    "lossless, bit for bit": random volumes of random size, 8 and 16 bits, smooth
//                  or noisy, any page size, decode to the volume, gradients to quantizedGradients
#include <algorithm>
#include <cstdint>
#include <queue>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference/common/volume.h"
#include "reference/leb/bit_stream.h"
#include "reference/leb/gradients.h"
#include "reference/leb/huffman.h"
#include "reference/leb/lead1_coder.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_stream.h"
#include "reference/leb/prediction.h"
#include "tests/property/property_seed.h"

namespace voxref::ref {
namespace leb_property_test {  // named: a unity build compiles several test files together

using property::coin;
using property::Rng;
using property::uniformInt;

constexpr std::initializer_list<std::uint64_t> kRegressionSeeds = {};

std::int64_t floorDiv2(std::int64_t a) { return a >= 0 ? a / 2 : -((-a + 1) / 2); }

TEST(LebProperty, PredictionDeltaReconstructsEveryValue) {
  property::forEachSeed(5000, kRegressionSeeds, [&](Rng& rng) {
    for (int i = 0; i < 100; ++i) {
      const int bits = static_cast<int>(uniformInt(rng, 1, 16));
      const bool isSigned = coin(rng, 30);
      const std::int64_t lo = isSigned ? -(std::int64_t{1} << (bits - 1)) : 0, hi = lo + (std::int64_t{1} << bits) - 1;
      const auto a = static_cast<std::int32_t>(uniformInt(rng, lo, hi)),
                 b = static_cast<std::int32_t>(uniformInt(rng, lo, hi)),
                 v = static_cast<std::int32_t>(uniformInt(rng, lo, hi));
      const std::int32_t p = predictMidpoint(a, b);
      ASSERT_EQ(p, floorDiv2(std::int64_t{a} + b)) << a << " " << b;
      const std::int32_t d = predictionDelta(v, p, bits);
      ASSERT_GE(d, -(std::int64_t{1} << (bits - 1))) << "bits " << bits;
      ASSERT_LT(d, std::int64_t{1} << (bits - 1)) << "bits " << bits;
      ASSERT_EQ((std::int64_t{v} - p - d) % (std::int64_t{1} << bits), 0) << "delta is the difference modulo 2^bits";
      ASSERT_EQ(reconstructSample(p, d, bits, isSigned), v)
          << "bits " << bits << " a " << a << " b " << b << " v " << v;
    }
  });
}

// Total cost sum count * length of an unlimited Huffman code (two smallest weights merged).
std::uint64_t huffmanCost(const std::vector<std::uint64_t>& counts) {
  std::priority_queue<std::uint64_t, std::vector<std::uint64_t>, std::greater<>> q;
  for (std::uint64_t c : counts)
    if (c) q.push(c);
  if (q.size() == 1) return q.top();  // one symbol: one bit each
  std::uint64_t cost = 0;
  while (q.size() > 1) {
    const std::uint64_t a = q.top();
    q.pop();
    const std::uint64_t b = q.top();
    q.pop();
    cost += a + b;  // every merge adds one bit to all symbols below it
    q.push(a + b);
  }
  return cost;
}
// The longest code of an unlimited Huffman code (depth of the merge tree).
int huffmanDepth(const std::vector<std::uint64_t>& counts) {
  using Node = std::pair<std::uint64_t, int>;  // weight, depth below
  std::priority_queue<Node, std::vector<Node>, std::greater<>> q;
  for (std::uint64_t c : counts)
    if (c) q.push({c, 0});
  if (q.size() == 1) return 1;
  while (q.size() > 1) {
    const Node a = q.top();
    q.pop();
    const Node b = q.top();
    q.pop();
    q.push({a.first + b.first, std::max(a.second, b.second) + 1});
  }
  return q.top().second;  // depends on tie order only when equal weights tie; used as a hint
}

std::vector<std::uint64_t> randomHistogram(Rng& rng, int symbols) {
  std::vector<std::uint64_t> counts(static_cast<std::size_t>(symbols));
  const int shape = static_cast<int>(uniformInt(rng, 0, 3));
  for (int s = 0; s < symbols; ++s) {
    if (coin(rng, 20)) continue;  // unused symbol
    switch (shape) {
      case 0:
        counts[s] = static_cast<std::uint64_t>(uniformInt(rng, 1, 1000));
        break;
      case 1:
        counts[s] = std::uint64_t{1} << uniformInt(rng, 0, 40);
        break;  // very skewed: long codes
      case 2:
        counts[s] = static_cast<std::uint64_t>(uniformInt(rng, 1, 3));
        break;  // many ties
      default:
        counts[s] = static_cast<std::uint64_t>(uniformInt(rng, 1, 1) + (s < 40 ? (std::uint64_t{1} << s) : 0));
        break;  // Fibonacci-like
    }
  }
  if (coin(rng, 5)) {  // exactly one used symbol
    std::fill(counts.begin(), counts.end(), 0);
    counts[static_cast<std::size_t>(uniformInt(rng, 0, symbols - 1))] =
        static_cast<std::uint64_t>(uniformInt(rng, 1, 99));
  }
  return counts;
}

TEST(LebProperty, HuffmanLengthsAreCompleteOptimalAndDecodable) {
  property::forEachSeed(10000, kRegressionSeeds, [&](Rng& rng) {
    const int symbols = static_cast<int>(uniformInt(rng, 1, 17));
    std::vector<std::uint64_t> counts = randomHistogram(rng, symbols);
    const auto used = std::count_if(counts.begin(), counts.end(), [](std::uint64_t c) { return c != 0; });
    if (used == 0) return;
    int maxLength = coin(rng, 50) ? kMaxCodeLength : static_cast<int>(uniformInt(rng, 1, kMaxCodeLength));
    while ((std::int64_t{1} << maxLength) < used) ++maxLength;
    const std::vector<std::uint8_t> lengths = huffmanCodeLengths(counts, maxLength);
    ASSERT_EQ(lengths.size(), counts.size());
    std::uint64_t kraft = 0, cost = 0;  // Kraft sum in units of 2^-maxLength
    for (std::size_t s = 0; s < counts.size(); ++s) {
      ASSERT_EQ(lengths[s] == 0, counts[s] == 0) << "symbol " << s;
      ASSERT_LE(lengths[s], maxLength);
      if (lengths[s]) kraft += std::uint64_t{1} << (maxLength - lengths[s]);
      cost += counts[s] * lengths[s];
    }
    if (used == 1) {
      ASSERT_EQ(kraft, std::uint64_t{1} << (maxLength - 1)) << "one used symbol has length 1";
    } else {
      ASSERT_EQ(kraft, std::uint64_t{1} << maxLength) << "Kraft sum must be exactly 1";
    }
    const std::uint64_t unlimited = huffmanCost(counts);
    ASSERT_GE(cost, unlimited);
    if (huffmanDepth(counts) <= maxLength) {
      ASSERT_EQ(cost, unlimited) << "optimal when the limit does not bind";
    }
    ASSERT_EQ(codeLengthProblem(lengths, maxLength), "");

    // Canonical codes: pairwise prefix-free; the table decodes each code under any suffix bits.
    const std::vector<std::uint32_t> codes = canonicalCodes(lengths);
    for (std::size_t i = 0; i < codes.size(); ++i)
      for (std::size_t j = 0; j < codes.size(); ++j) {
        if (i == j || !lengths[i] || !lengths[j] || lengths[i] > lengths[j]) continue;
        ASSERT_NE(codes[j] >> (lengths[j] - lengths[i]), codes[i]) << "code " << i << " is a prefix of code " << j;
      }
    const HuffmanDecodeTable table(lengths);
    for (std::size_t s = 0; s < codes.size(); ++s) {
      if (!lengths[s]) continue;
      const int extra = table.bits() - lengths[s];
      ASSERT_GE(extra, 0);
      const auto suffix = static_cast<std::uint32_t>(uniformInt(rng, 0, (std::int64_t{1} << extra) - 1));
      const std::uint16_t e = table.entry((codes[s] << extra) | suffix);
      ASSERT_EQ(e >> 4, s);
      ASSERT_EQ(e & 15, lengths[s]);
    }
  });
}

std::int32_t randomDelta(Rng& rng, int bits, int spread) {
  const int lead = static_cast<int>(std::min<std::int64_t>(bits, uniformInt(rng, 0, spread)));
  if (lead == 0) return 0;
  if (lead == bits)
    return coin(rng, 50) ? -(1 << (bits - 1))
                         : static_cast<std::int32_t>(uniformInt(rng, -(1 << (bits - 1)), (1 << (bits - 1)) - 1));
  const auto mag =
      static_cast<std::int32_t>(uniformInt(rng, std::int64_t{1} << (lead - 1), (std::int64_t{1} << lead) - 1));
  return coin(rng, 50) ? -mag : mag;
}

TEST(LebProperty, Lead1CodeDecodesWhatItEncodes) {
  property::forEachSeed(1000, kRegressionSeeds, [&](Rng& rng) {
    const int bits = coin(rng, 50) ? 8 : 16;
    const int spread = static_cast<int>(uniformInt(rng, 0, bits));
    std::vector<std::vector<std::int32_t>> pages(static_cast<std::size_t>(uniformInt(rng, 1, 8)));
    for (auto& page : pages) {
      page.resize(static_cast<std::size_t>(uniformInt(rng, 0, 300)));
      for (std::int32_t& d : page) d = randomDelta(rng, bits, spread);
    }
    Lead1Counter counter(bits);
    for (const auto& page : pages) counter.add(page);
    const Lead1Code code = counter.code();
    ASSERT_EQ(lead1CodeProblem(code), "");
    const Lead1Encoder encoder(code);
    const Lead1Decoder decoder(code);
    for (std::size_t i = 0; i < pages.size(); ++i) {
      BitWriter w;
      encoder.encodePage(pages[i], w);
      const std::string bytes = w.finish();
      std::vector<std::int32_t> back(pages[i].size());
      decoder.decodePage(bytes, back, 0, "page " + std::to_string(i));
      ASSERT_EQ(back, pages[i]) << "page " << i << " of " << bits << "-bit deltas";
    }
  });
}

TEST(LebProperty, RandomVolumesRoundTripLosslessly) {
  property::forEachSeed(400, kRegressionSeeds, [&](Rng& rng) {
    const int bits = coin(rng, 50) ? 8 : 16;
    const Dims3 dims{static_cast<int>(uniformInt(rng, 1, 20)), static_cast<int>(uniformInt(rng, 1, 20)),
                     static_cast<int>(uniformInt(rng, 1, 20))};
    Volume<std::uint16_t> v(dims);
    const std::int64_t maxValue = (std::int64_t{1} << bits) - 1;
    const int mode = static_cast<int>(uniformInt(rng, 0, 2));
    std::int64_t prev = uniformInt(rng, 0, maxValue);
    for (std::uint16_t& x : v.data()) {
      if (mode == 0)
        prev = uniformInt(rng, 0, maxValue);  // noise
      else if (mode == 1)
        prev = std::clamp<std::int64_t>(prev + uniformInt(rng, -4, 4), 0, maxValue);  // smooth
      else
        prev = coin(rng, 90) ? prev : (coin(rng, 50) ? 0 : maxValue);  // flat with extremes
      x = static_cast<std::uint16_t>(prev);
    }
    LebEncodeOptions options;
    options.pageBits = static_cast<int>(uniformInt(rng, kMinLebPageBits, 12));
    options.gradients = coin(rng, 50);
    options.threads = 1;
    const LebStream stream = parseLebStream(encodeLeb(v, bits, options));
    const LebDecoded d = decodeLeb(stream, 1);
    ASSERT_EQ(d.data.dims(), dims);
    ASSERT_EQ(d.data.data(), v.data()) << bits << "-bit " << dims[0] << "x" << dims[1] << "x" << dims[2]
                                       << " page bits " << options.pageBits;
    if (options.gradients) {
      ASSERT_EQ(d.gradients, quantizedGradients(v));
    } else {
      ASSERT_TRUE(d.gradients.empty());
    }
  });
}

}  // namespace leb_property_test
}  // namespace voxref::ref
