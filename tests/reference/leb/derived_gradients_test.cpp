// Streams that derive their gradients from the data (reference/leb/FORMAT.md, header byte 23;
// LebEncodeOptions::deriveGradients): what they hold, what the whole-volume decoder and random
// access give, and what the parser refuses. The expected gradients come from the definition,
// quantizeGradient of centralGradient per sample (gradients.h), not from the decoder's slices.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/leb/gradients.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_padding.h"
#include "reference/leb/leb_reader.h"
#include "tests/reference/leb/leb_test_volumes.h"

namespace voxref::ref {
namespace {

using test_support::noise;
using test_support::smooth;

// The gradients by their definition, one sample at a time.
std::vector<std::int8_t> definedGradients(const Volume<std::uint16_t>& v) {
  const Dims3& d = v.dims();
  std::vector<std::int8_t> g(3 * v.data().size());
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x)
        quantizeGradient(centralGradient(v.data().data(), d, x, y, z), g.data() + 3 * v.index(x, y, z));
  return g;
}

std::string encodeWith(const Volume<std::uint16_t>& v, int bits, int pageBits, LebCoder coder, bool gradients,
                       bool derive) {
  LebEncodeOptions o;
  o.pageBits = pageBits;
  o.coder = coder;
  o.gradients = gradients;
  o.deriveGradients = derive;
  return encodeLeb(v, bits, o);
}

struct Case {
  std::string what;
  Volume<std::uint16_t> volume;
  int bits;
};

std::vector<Case> edgeCases() {
  Volume<std::uint16_t> spike({33, 33, 33}, 0);
  spike.at(16, 9, 30) = 255;
  Volume<std::uint16_t> wide = noise({19, 23, 17}, 16, 6);
  wide.at(1, 0, 0) = 65535;
  return {{"constant", Volume<std::uint16_t>({17, 17, 17}, 77), 8},
          {"one spike", spike, 8},
          {"full-range noise", noise({20, 31, 9}, 8, 3), 8},
          {"2x2x2", noise({2, 2, 2}, 8, 4), 8},
          {"1x1x1", noise({1, 1, 1}, 8, 5), 8},
          {"a row", noise({40, 1, 1}, 8, 7), 8},
          {"a plane", noise({9, 1, 13}, 8, 8), 8},
          {"37x5x101", smooth({37, 5, 101}, 8), 8},
          {"uint16 noise", wide, 16},
          {"uint16 smooth, unpadded grid", smooth({33, 33, 33}, 16), 16}};
}

TEST(DerivedGradients, TheWholeDecodeGivesTheDefinitionsGradients) {
  for (const Case& c : edgeCases())
    for (const LebCoder coder : test_support::kLebCoders)
      for (const int pageBits : {4, 12}) {
        SCOPED_TRACE(c.what + ", " + std::string(lebCoderName(coder)) + ", page bits " + std::to_string(pageBits));
        const LebStream s = parseLebStream(encodeWith(c.volume, c.bits, pageBits, coder, true, true));
        EXPECT_TRUE(s.derivedGradients);
        EXPECT_TRUE(s.hasGradients());
        ASSERT_EQ(s.channels.size(), 1u);
        const LebDecoded d = decodeLeb(s);
        EXPECT_EQ(d.data.data(), c.volume.data());
        EXPECT_EQ(d.gradients, definedGradients(c.volume));
      }
}

// The stream is the data-only stream with byte 23 set (and the header's CRC with it): the
// gradients cost no byte.
TEST(DerivedGradients, TheStreamIsTheDataAloneWithItsHeaderByteSet) {
  for (const Case& c : edgeCases())
    for (const LebCoder coder : test_support::kLebCoders) {
      SCOPED_TRACE(c.what + ", " + std::string(lebCoderName(coder)));
      const std::string derived = encodeWith(c.volume, c.bits, 12, coder, true, true);
      const std::string dataOnly = encodeWith(c.volume, c.bits, 12, coder, false, false);
      ASSERT_EQ(derived.size(), dataOnly.size());
      EXPECT_EQ(static_cast<int>(derived[23]), 1);
      EXPECT_EQ(static_cast<int>(dataOnly[23]), 0);
      EXPECT_EQ(derived.substr(0, 23), dataOnly.substr(0, 23));
      EXPECT_EQ(derived.substr(24, 8), dataOnly.substr(24, 8));
      EXPECT_EQ(derived.substr(36), dataOnly.substr(36));
      EXPECT_FALSE(parseLebStream(dataOnly).hasGradients());
    }
}

TEST(DerivedGradients, TheSameBytesOnEveryThreadCountAndTheWindowRises) {
  const Volume<std::uint16_t> v = smooth({37, 29, 45}, 8);
  const LebStream s = parseLebStream(encodeWith(v, 8, 8, LebCoder::Lead1, true, true));
  const std::vector<std::int8_t> want = definedGradients(v);
  for (const int threads : {1, 2, 3}) {
    Volume<std::uint16_t> data(v.dims());
    std::vector<std::int8_t> g(want.size(), 0);
    std::vector<double> seen;
    decodeLebInto(s, LebVolumeOut{v.dims(), 8, nullptr, data.data().data(), g.data()}, threads,
                  [&](double done) { seen.push_back(done); });
    EXPECT_EQ(data.data(), v.data()) << threads;
    EXPECT_EQ(g, want) << threads;
    ASSERT_FALSE(seen.empty());
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  }
}

// The gradients are derived only when asked for; a stream that stores them always decodes them.
// The memory bound counts the derived gradients as it counts stored ones, and the shell of the one
// channel (a stored gradients channel has a shell of its own).
TEST(DerivedGradients, TheGradientsAreDerivedWhenAskedAndCountInTheMemoryBound) {
  const Volume<std::uint16_t> v = smooth({9, 10, 11}, 8);
  const LebStream derived = parseLebStream(encodeWith(v, 8, 12, LebCoder::Lead1, true, true));
  const LebStream stored = parseLebStream(encodeWith(v, 8, 12, LebCoder::Lead1, true, false));
  const std::uint64_t shell = LebPadding::tableBytes(derived.grid, derived.dims);
  EXPECT_GT(shell, 0u);
  EXPECT_EQ(lebDecodeMemoryBytes(derived), 5u * 9 * 10 * 11 + shell);
  EXPECT_EQ(lebDecodeMemoryBytes(stored), 5u * 9 * 10 * 11 + 2 * shell);
  Volume<std::uint16_t> data(v.dims());
  std::vector<double> seen;
  decodeLebInto(derived, LebVolumeOut{v.dims(), 8, nullptr, data.data().data(), nullptr}, 0,
                [&](double done) { seen.push_back(done); });
  EXPECT_EQ(data.data(), v.data());
  ASSERT_FALSE(seen.empty());
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);  // the work done is the work asked for
  EXPECT_THROW(decodeLebInto(stored, LebVolumeOut{v.dims(), 8, nullptr, data.data().data(), nullptr}),
               std::invalid_argument);
  LebEncodeOptions o;
  o.gradients = false;
  o.deriveGradients = true;
  EXPECT_THROW(encodeLeb(v, 8, o), std::invalid_argument);
}

// Random access: at every grid point of a small grid (the padding included, whose gradients are
// predictions) and at random points of larger ones, a derived stream gives what a stream that
// stores the same gradients gives, asked in every order, on a memo small enough to evict.
TEST(DerivedGradients, RandomAccessEqualsAStreamThatStoresThem) {
  struct Grid {
    Volume<std::uint16_t> volume;
    bool everyPoint;
  };
  for (const LebCoder coder : test_support::kLebCoders)
    for (const Grid& g : {Grid{noise({9, 6, 11}, 8, 21), true}, Grid{smooth({37, 5, 101}, 8), false},
                          Grid{noise({20, 31, 9}, 16, 22), false}}) {
      SCOPED_TRACE(std::string(lebCoderName(coder)) + " " + dimsText(g.volume.dims()));
      const int bits = g.volume.data().end() != std::find_if(g.volume.data().begin(), g.volume.data().end(),
                                                             [](std::uint16_t s) { return s > 255; })
                           ? 16
                           : 8;
      auto derived =
          std::make_shared<const LebStream>(parseLebStream(encodeWith(g.volume, bits, 6, coder, true, true)));
      auto stored =
          std::make_shared<const LebStream>(parseLebStream(encodeWith(g.volume, bits, 6, coder, true, false)));
      LebReader a(derived, 1 << 12), b(stored, 1 << 20);
      std::vector<GridPoint> points;
      const int n = derived->grid.pointsPerAxis();
      if (g.everyPoint) {
        for (int z = 0; z < n; ++z)
          for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) points.push_back({x, y, z});
      } else {
        std::mt19937 rng(31);
        for (int i = 0; i < 4000; ++i)
          points.push_back({static_cast<int>(rng() % static_cast<unsigned>(n)),
                            static_cast<int>(rng() % static_cast<unsigned>(n)),
                            static_cast<int>(rng() % static_cast<unsigned>(n))});
      }
      int i = 0;
      for (const GridPoint& p : points) {
        const LebReader::SampleAndGradient want = b.sampleAndGradient(p);
        switch (i++ % 3) {
          case 0: {
            const LebReader::SampleAndGradient got = a.sampleAndGradient(p);
            ASSERT_EQ(got.sample, want.sample);
            ASSERT_EQ(got.gradient, want.gradient);
            break;
          }
          case 1:
            ASSERT_EQ(a.gradient(p), want.gradient);
            ASSERT_EQ(a.sample(p), want.sample);
            break;
          default:
            ASSERT_EQ(a.sample(p), want.sample);
            ASSERT_EQ(a.gradient(p), want.gradient);
        }
      }
      EXPECT_THROW(a.reconstructPage(LebChannelKind::Gradients, 0), std::invalid_argument);
    }
}

// Byte 23 is 0 or 1, and 1 only with the data channel alone.
TEST(DerivedGradients, TheParserRefusesAGradientsByteThatDoesNotFit) {
  const Volume<std::uint16_t> v = smooth({9, 10, 11}, 8);
  auto withByte23 = [](std::string b, char value) {
    b[23] = value;
    const std::uint32_t crc = crc32(std::string_view(b).substr(0, 32));
    for (int i = 0; i < 4; ++i) b[32 + static_cast<std::size_t>(i)] = static_cast<char>((crc >> (8 * i)) & 0xff);
    return b;
  };
  auto errorOf = [](std::string b) -> std::string {
    try {
      parseLebStream(std::move(b));
    } catch (const StreamError& e) {
      return e.what();
    }
    return "";
  };
  const std::string stored = encodeWith(v, 8, 12, LebCoder::Lead1, true, false);
  const std::string dataOnly = encodeWith(v, 8, 12, LebCoder::Lead1, false, false);
  EXPECT_NE(errorOf(withByte23(stored, 1)).find("offset 23: gradients: 1 (derived from the data) with 2 channels"),
            std::string::npos)
      << errorOf(withByte23(stored, 1));
  EXPECT_NE(errorOf(withByte23(dataOnly, 2)).find("offset 23: gradients: expected 0..1, got 2"), std::string::npos)
      << errorOf(withByte23(dataOnly, 2));
  EXPECT_EQ(errorOf(withByte23(dataOnly, 1)), "");
}

}  // namespace
}  // namespace voxref::ref
