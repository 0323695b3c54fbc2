#include "reference/leb/leb_codec.h"

#include <algorithm>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/leb/gradients.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_padding.h"
#include "reference/leb/leb_page.h"
#include "reference/leb/leb_reader.h"
#include "tests/reference/leb/leb_test_volumes.h"

namespace voxref::ref {
namespace {

using test_support::noise;
using test_support::smooth;
constexpr const auto& kCoders = test_support::kLebCoders;

void expectRoundTrip(const Volume<std::uint16_t>& v, int bits, int pageBits, const std::string& what, LebCoder coder) {
  SCOPED_TRACE(what + ", page bits " + std::to_string(pageBits) + ", coder " + std::string(lebCoderName(coder)));
  LebEncodeOptions o;
  o.pageBits = pageBits;
  o.coder = coder;
  const LebStream s = parseLebStream(encodeLeb(v, bits, o));
  EXPECT_EQ(s.coder, coder);
  const LebDecoded d = decodeLeb(s);
  ASSERT_EQ(d.data.dims(), v.dims());
  EXPECT_EQ(d.data.data(), v.data());
  EXPECT_EQ(d.gradients, quantizedGradients(v));
  const LebStats st = lebStats(s);
  EXPECT_EQ(st.volumePoints, sampleCount(v.dims()));
  EXPECT_EQ(st.streamBytes, s.bytes.size());
}

// encodeLebTo's contract (leb_codec.h): every byte of the stream written exactly once, the pages
// in order, each descriptor after its pages, the header last; the same bytes as encodeLeb, for
// 8-bit samples given at 8 bits or widened to 16, and any gradients the caller gives round-trip.
TEST(LebCodec, TheStreamingEncoderWritesEachByteOnceInTheDocumentedOrder) {
  const Volume<std::uint16_t> v = smooth({37, 21, 13}, 8);
  const std::vector<std::uint8_t> narrow(v.data().begin(), v.data().end());
  const std::vector<std::int8_t> g = quantizedGradients(v);
  LebEncodeOptions o;
  o.pageBits = 6;
  int windows = 0;
  double last = 0.0;
  o.window = [&](double done) {
    ++windows;
    EXPECT_GE(done, last);  // the fraction of the work rises to 1
    EXPECT_LE(done, 1.0 + 1e-12);
    last = done;
  };
  std::vector<std::pair<std::uint64_t, std::string>> writes;
  const std::uint64_t total =
      encodeLebTo(LebVolumeIn{v.dims(), 8, narrow.data(), nullptr, g.data()}, o,
                  [&](std::uint64_t at, std::string_view b) { writes.emplace_back(at, std::string(b)); });
  EXPECT_GT(windows, 0);
  EXPECT_NEAR(last, 1.0, 1e-12);
  ASSERT_FALSE(writes.empty());
  EXPECT_EQ(writes.back().first, 0u);  // the header, last
  EXPECT_EQ(writes.back().second.size(), kLebHeaderBytes);
  std::string stream(total, '\0');
  std::vector<int> times(total, 0);
  for (const auto& [at, b] : writes) {
    ASSERT_LE(at + b.size(), total);
    stream.replace(at, b.size(), b);
    for (std::size_t i = 0; i < b.size(); ++i) ++times[at + i];
  }
  EXPECT_TRUE(std::all_of(times.begin(), times.end(), [](int n) { return n == 1; }));
  o.window = {};
  EXPECT_EQ(stream, encodeLeb(v, 8, o));
  // Gradients of the caller's own (here reversed) are what the stream holds.
  const std::vector<std::int8_t> mine(g.rbegin(), g.rend());
  const std::string other = encodeLeb(LebVolumeIn{v.dims(), 8, narrow.data(), nullptr, mine.data()}, o);
  EXPECT_EQ(decodeLeb(parseLebStream(other)).gradients, mine);
  EXPECT_THROW(encodeLebTo(LebVolumeIn{v.dims(), 16, narrow.data(), nullptr, g.data()}, o, {}), std::invalid_argument);
  EXPECT_THROW(encodeLebTo(LebVolumeIn{v.dims(), 8, narrow.data(), nullptr, nullptr}, o, {}), std::invalid_argument);
}

TEST(LebCodec, RoundTripOfTheEdgeCases) {
  for (const LebCoder coder : kCoders)
    for (int pageBits : {4, 12}) {
      auto expectRoundTrip = [&](const Volume<std::uint16_t>& v, int bits, int pb, const std::string& what) {
        voxref::ref::expectRoundTrip(v, bits, pb, what, coder);
      };
      expectRoundTrip(Volume<std::uint16_t>({17, 17, 17}, 77), 8, pageBits, "constant");
      Volume<std::uint16_t> spike({33, 33, 33}, 0);
      spike.at(16, 9, 30) = 255;
      expectRoundTrip(spike, 8, pageBits, "one spike");
      expectRoundTrip(noise({20, 31, 9}, 8, 3), 8, pageBits, "full-range noise");
      expectRoundTrip(noise({2, 2, 2}, 8, 4), 8, pageBits, "2x2x2");
      expectRoundTrip(noise({1, 1, 1}, 8, 5), 8, pageBits, "1x1x1");
      expectRoundTrip(smooth({37, 5, 101}, 8), 8, pageBits, "37x5x101");
      Volume<std::uint16_t> wide = noise({19, 23, 17}, 16, 6);
      wide.at(0, 0, 0) = 0;
      wide.at(1, 0, 0) = 65535;
      wide.at(2, 0, 0) = 0;
      expectRoundTrip(wide, 16, pageBits, "uint16 using all 16 bits");
      expectRoundTrip(smooth({65, 65, 65}, 16), 16, pageBits, "uint16 smooth, unpadded grid");
      expectRoundTrip(Volume<std::uint16_t>({9, 9, 9}, 65535), 16, pageBits, "uint16 constant at the top");
    }
}

TEST(LebCodec, SameBytesForEveryThreadCount) {
  const Volume<std::uint16_t> v = smooth({40, 30, 20}, 8);
  for (const LebCoder coder : kCoders) {
    LebEncodeOptions one, two;
    one.threads = 1;
    two.threads = 2;
    one.coder = two.coder = coder;
    const std::string a = encodeLeb(v, 8, one), b = encodeLeb(v, 8, two);
    EXPECT_EQ(a, b);
    const LebStream s = parseLebStream(a);
    EXPECT_EQ(decodeLeb(s, 1).data.data(), decodeLeb(s, 2).data.data());
  }
}

// The adaptive coder's stream (reference/leb/FORMAT.md, header byte 22 and "Adaptive pages"): version 3, coder
// 1, the same stored pages as the lead-1 stream of the volume, no code table in the descriptors,
// and every page exactly the bytes encodeAdaptivePage makes of that page's lead-1 deltas.
TEST(LebCodec, AnAdaptiveStreamCodesTheSameDeltasInItsOwnPages) {
  const Volume<std::uint16_t> v = smooth({37, 21, 13}, 8);
  LebEncodeOptions o;
  o.pageBits = 7;
  const LebStream lead1 = parseLebStream(encodeLeb(v, 8, o));
  o.coder = LebCoder::Adaptive;
  const LebStream adaptive = parseLebStream(encodeLeb(v, 8, o));
  EXPECT_EQ(lead1.bytes[4], 2);
  EXPECT_EQ(adaptive.bytes[4], 3);
  EXPECT_EQ(adaptive.bytes[22], 1);
  ASSERT_EQ(adaptive.channels.size(), 2u);
  for (std::size_t ci = 0; ci < 2; ++ci) {
    const LebChannel &a = adaptive.channels[ci], &l = lead1.channels[ci];
    EXPECT_EQ(a.storedPage, l.storedPage);
    EXPECT_EQ(a.decoder, nullptr);
    EXPECT_EQ(a.descriptorBytes, lebDescriptorSize(a.valueBits, a.storedPage.size(), LebCoder::Adaptive));
    for (std::size_t j = 0; j < a.storedPage.size(); ++j) {
      const std::uint64_t points = insidePointsOfPage(HzOrder(lead1.grid), v.dims(), o.pageBits, l.storedPage[j]);
      std::vector<std::int32_t> deltas(static_cast<std::size_t>(points) * static_cast<std::size_t>(l.components));
      LebPageReader r = openPage(lead1, l, l.storedPage[j]);
      r.read(deltas);
      r.finish();
      EXPECT_EQ(adaptive.page(a, j), encodeAdaptivePage(deltas, a.valueBits, a.components))
          << "channel " << ci << ", page " << j;
    }
  }
  const LebDecoded d = decodeLeb(adaptive);
  EXPECT_EQ(d.data.data(), v.data());
  EXPECT_EQ(d.gradients, quantizedGradients(v));
}

// The deltas of equation 2 from the closed form, point by point in H order (HzOrder::point,
// splitEdge): the sample minus the floor of its split edge's endpoints' mean, wrapped to 8 bits.
// In a volume with padding only the points whose split edge lies inside the volume are checked
// (the others are predicted from the padding, leb_padding.h): the encoder reads those endpoints
// at index offsets, and this catches an offset or a boundary test that is wrong.
TEST(LebCodec, DeltasAreTheSplitEdgeMidpointPrediction) {
  for (const Dims3 d : {Dims3{17, 17, 17}, Dims3{13, 17, 10}, Dims3{17, 5, 16}}) {
    SCOPED_TRACE(dimsText(d));
    const Volume<std::uint16_t> v = noise(d, 8, 7);
    const LebGrid g = lebGridCovering(d);
    const HzOrder order(g);
    const std::vector<std::int32_t> deltas = lebDeltas(v, 8, LebChannelKind::Data);
    auto inside = [&](const GridPoint& q) { return q[0] < d[0] && q[1] < d[1] && q[2] < d[2]; };
    auto value = [&](const GridPoint& q) { return static_cast<int>(v.at(q[0], q[1], q[2])); };
    std::size_t next = 0, checked = 0;
    for (std::uint64_t h = 0; h < order.size(); ++h) {
      const GridPoint p = order.point(h);
      if (!inside(p)) continue;
      ASSERT_LT(next, deltas.size());
      const std::int32_t delta = deltas[next++];
      int prediction = 0;
      if (!isRootCorner(g, p)) {
        const SplitEdge e = splitEdge(g, p);
        if (!inside(e.a) || !inside(e.b)) continue;
        prediction = (value(e.a) + value(e.b)) / 2;  // both >= 0: floor
      }
      EXPECT_EQ(delta, ((value(p) - prediction + 128) & 255) - 128) << pointText(p);
      ++checked;
    }
    EXPECT_EQ(next, deltas.size());
    EXPECT_GT(checked, deltas.size() / 2);
  }
}

TEST(LebCodec, PaddingCostsNoPayload) {
  // The same 33^3 data padded into a 65^3 grid (by one extra sample along x) codes the same
  // deltas plus those of the extra samples; the padding itself adds no coded values.
  const LebStream s = parseLebStream(encodeLeb(smooth({34, 33, 33}, 8), 8));
  const LebStats st = lebStats(s);
  EXPECT_EQ(st.k, 6);
  EXPECT_EQ(st.gridPoints, 65u * 65u * 65u);
  EXPECT_EQ(st.channels[0].codedValues, 34u * 33u * 33u);
  EXPECT_GT(st.ratio(), 1.0);
}

TEST(LebCodec, RejectsBadInput) {
  EXPECT_THROW(encodeLeb(Volume<std::uint16_t>({4, 4, 4}, 256), 8), std::invalid_argument);
  EXPECT_THROW(encodeLeb(Volume<std::uint16_t>({4, 4, 4}, 1), 12), std::invalid_argument);
  LebEncodeOptions o;
  o.pageBits = 3;
  EXPECT_THROW(encodeLeb(Volume<std::uint16_t>({4, 4, 4}, 1), 8, o), std::invalid_argument);
}

TEST(LebReader, RandomAccessEqualsTheWholeDecode) {
  for (const LebCoder coder : kCoders)
    for (const Dims3 dims : {Dims3{37, 5, 101}, Dims3{33, 33, 33}}) {
      SCOPED_TRACE(std::string(lebCoderName(coder)));
      const Volume<std::uint16_t> v = smooth(dims, 8);
      LebEncodeOptions o;
      o.pageBits = 8;
      o.coder = coder;
      auto s = std::make_shared<const LebStream>(parseLebStream(encodeLeb(v, 8, o)));
      const std::vector<std::int8_t> g = quantizedGradients(v);
      LebReader reader(s, 1 << 16);
      std::mt19937 rng(9);
      for (int i = 0; i < 3000; ++i) {
        const int x = static_cast<int>(rng() % static_cast<unsigned>(dims[0])),
                  y = static_cast<int>(rng() % static_cast<unsigned>(dims[1])),
                  z = static_cast<int>(rng() % static_cast<unsigned>(dims[2]));
        ASSERT_EQ(reader.sample({x, y, z}), v.at(x, y, z));
        const auto gr = reader.gradient({x, y, z});
        const std::size_t at = 3 * v.index(x, y, z);
        ASSERT_EQ(gr[0], g[at]);
        ASSERT_EQ(gr[1], g[at + 1]);
        ASSERT_EQ(gr[2], g[at + 2]);
      }
      EXPECT_GT(reader.cacheStats().hits, 0u);
      EXPECT_LE(reader.cacheStats().peakBytes, std::size_t{1} << 16);
      // Both channels in one query, and the channels asked for in turn in every order (a memo entry
      // that knows one channel gains the other), on a small memo that is emptied often.
      LebReader both(s, 1 << 12);
      for (int i = 0; i < 3000; ++i) {
        const GridPoint p{static_cast<int>(rng() % static_cast<unsigned>(dims[0])),
                          static_cast<int>(rng() % static_cast<unsigned>(dims[1])),
                          static_cast<int>(rng() % static_cast<unsigned>(dims[2]))};
        const std::size_t at = 3 * v.index(p[0], p[1], p[2]);
        const std::array<std::int8_t, 3> want{g[at], g[at + 1], g[at + 2]};
        switch (i % 3) {
          case 0: {
            const LebReader::SampleAndGradient sg = both.sampleAndGradient(p);
            ASSERT_EQ(sg.sample, v.at(p[0], p[1], p[2]));
            ASSERT_EQ(sg.gradient, want);
            break;
          }
          case 1:
            ASSERT_EQ(both.gradient(p), want);
            ASSERT_EQ(both.sample(p), v.at(p[0], p[1], p[2]));
            break;
          default:
            ASSERT_EQ(both.sample(p), v.at(p[0], p[1], p[2]));
            ASSERT_EQ(both.gradient(p), want);
            ASSERT_EQ(both.sampleAndGradient(p).gradient, want);
        }
      }
      // Whole pages: the points inside the volume equal the volume.
      const HzOrder order(s->grid);
      for (std::uint64_t page = 0; page < s->pageCount(); page += 7) {
        const auto values = reader.reconstructPage(LebChannelKind::Data, page);
        for (std::uint64_t i = 0; i < (std::uint64_t{1} << s->pageBits) && (page << s->pageBits) + i < order.size();
             ++i) {
          const GridPoint p = order.point((page << s->pageBits) + i);
          if (p[0] < dims[0] && p[1] < dims[1] && p[2] < dims[2]) {
            ASSERT_EQ(values[static_cast<std::size_t>(i)], v.at(p[0], p[1], p[2]));
          }
        }
      }
    }
}

// Noise of 8 and 16 bits gives deltas over the whole two's complement range of each; the cache
// keeps them a byte each at 8 bits and two at 16 (decoded_page.h), so a 16-bit delta cut to a byte
// shows here. Every point, read in random order, equals the volume and its quantized gradients,
// with pages evicted and decoded again under a small budget.
TEST(LebReader, EveryPointOfNoiseEqualsTheVolume) {
  for (const LebCoder coder : kCoders)
    for (const int bits : {8, 16}) {
      SCOPED_TRACE(std::string(lebCoderName(coder)) + ", " + std::to_string(bits) + " bits");
      const Volume<std::uint16_t> v = noise({13, 11, 9}, bits, 23u + static_cast<unsigned>(bits));
      LebEncodeOptions o;
      o.pageBits = 6;
      o.coder = coder;
      auto s = std::make_shared<const LebStream>(parseLebStream(encodeLeb(v, bits, o)));
      const std::vector<std::int8_t> g = quantizedGradients(v);
      LebReader reader(s, 1 << 11);
      std::vector<GridPoint> points;
      for (int z = 0; z < 9; ++z)
        for (int y = 0; y < 11; ++y)
          for (int x = 0; x < 13; ++x) points.push_back({x, y, z});
      std::shuffle(points.begin(), points.end(), std::mt19937(5));
      for (const GridPoint& p : points) {
        const LebReader::SampleAndGradient sg = reader.sampleAndGradient(p);
        const std::size_t at = 3 * v.index(p[0], p[1], p[2]);
        ASSERT_EQ(sg.sample, v.at(p[0], p[1], p[2])) << p[0] << " " << p[1] << " " << p[2];
        ASSERT_EQ(sg.gradient, (std::array<std::int8_t, 3>{g[at], g[at + 1], g[at + 2]}));
      }
      EXPECT_GT(reader.cacheStats().evictions, 0u);
    }
}

TEST(LebReader, ABudgetOfZeroDecodesEveryTimeAndStillAnswers) {
  const Volume<std::uint16_t> v = smooth({17, 17, 17}, 8);
  auto s = std::make_shared<const LebStream>(parseLebStream(encodeLeb(v, 8)));
  LebReader reader(s, 0);
  EXPECT_EQ(reader.sample({3, 4, 5}), v.at(3, 4, 5));
  EXPECT_EQ(reader.sample({3, 4, 5}), v.at(3, 4, 5));
  EXPECT_EQ(reader.cacheStats().hits, 0u);
  EXPECT_EQ(reader.cacheStats().bytes, 0u);
  EXPECT_THROW(reader.sample({17, 40, 0}), std::invalid_argument);
}

// --- Corrupt streams ------------------------------------------------------------------------

class LebCorrupt : public ::testing::Test {
 protected:
  virtual LebCoder coder() const { return LebCoder::Lead1; }
  void SetUp() override {
    LebEncodeOptions o;
    o.pageBits = 6;
    o.coder = coder();
    bytes = encodeLeb(smooth({9, 7, 5}, 8), 8, o);
    layout = parseLebStream(bytes);
  }
  static void put32(std::string& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xff);
  }
  // Recomputes every checksum, so that a test reaches the check behind them.
  void fixCrcs(std::string& b) const {
    put32(b, 32, crc32(std::string_view(b).substr(0, 32)));
    for (const LebChannel& c : layout.channels) {
      const std::size_t pages = c.pageCrc.size();
      const std::size_t crcs = c.descriptorOffset + c.descriptorBytes - 4 - 4 * pages;
      for (std::size_t p = 0; p < pages; ++p)
        put32(b, crcs + 4 * p,
              crc32(std::string_view(b).substr(c.payloadOffset + c.pageOffset[p],
                                               c.pageOffset[p + 1] - c.pageOffset[p])));
      put32(b, c.descriptorOffset + c.descriptorBytes - 4,
            crc32(std::string_view(b).substr(c.descriptorOffset, c.descriptorBytes - 4)));
    }
  }
  static std::string errorOf(std::string b) { return test_support::lebDecodeError(std::move(b)); }
  std::size_t tableAt(const LebChannel& c) const { return c.descriptorOffset + 20; }
  std::size_t pageIndicesAt(const LebChannel& c) const { return tableAt(c) + c.code.lengths.size(); }
  std::size_t pageLengthsAt(const LebChannel& c) const { return pageIndicesAt(c) + 4 * c.storedPage.size(); }

  std::string bytes;
  LebStream layout;
};

TEST_F(LebCorrupt, TheIntactStreamDecodes) { EXPECT_EQ(errorOf(bytes), ""); }

TEST_F(LebCorrupt, NotAStreamAndTruncated) {
  EXPECT_EQ(errorOf("JUNK" + bytes.substr(4)), "offset 0: magic: expected 'VXLB' (not an LEB stream)");
  EXPECT_NE(errorOf(bytes.substr(0, bytes.size() - 1))
                .find("total_bytes: the header describes " + std::to_string(bytes.size()) + " bytes, the stream has " +
                      std::to_string(bytes.size() - 1) + " (truncated)"),
            std::string::npos);
  EXPECT_NE(errorOf(bytes.substr(0, 20)).find("the stream ends after"), std::string::npos);
}

TEST_F(LebCorrupt, OversizedClaimsAreRefusedBeforeAllocating) {
  std::string b = bytes;
  b[7] = 12;  // k
  fixCrcs(b);
  EXPECT_EQ(errorOf(b), "offset 7: k: expected 0..11, got 12");
  b = bytes;
  b[7] = 10;  // a 1025^3 grid: its page table would not fit the stream
  put32(b, 8, 1025);
  put32(b, 12, 1025);
  put32(b, 16, 1025);
  fixCrcs(b);
  const std::string e = errorOf(b);
  EXPECT_NE(e.find("page_count: expected"), std::string::npos) << e;
}

// The contract of leb_stream.h ("Memory: ..."): sizes a header claims are checked against the
// stream's length before anything is allocated for them.
TEST_F(LebCorrupt, HugeClaimedSizesAreRefusedBeforeAllocating) {
  auto put64 = [](std::string& b, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xff);
  };
  const std::uint64_t terabyte = std::uint64_t{1} << 40;
  // total_bytes of 2^40 (header CRC remade).
  std::string b = bytes;
  put64(b, 24, terabyte);
  put32(b, 32, crc32(std::string_view(b).substr(0, 32)));
  EXPECT_EQ(errorOf(b), "offset 24: total_bytes: the header describes 1099511627776 bytes, the stream has " +
                            std::to_string(b.size()) + " (truncated)");
  // payload_bytes of 2^40 in the data channel's descriptor (offset 36 + 12).
  b = bytes;
  put64(b, 48, terabyte);
  EXPECT_EQ(errorOf(b), "offset 48: payload_bytes: 1099511627776, but the pages add up to " +
                            std::to_string(layout.channels[0].payloadBytes()));
  // The largest grid, 1025^3, in pages of 2^4: 67305665 pages, all claimed stored: a page table of
  // 12 bytes each (and the descriptor CRC) that the stream cannot hold; the table starts after the
  // 9 x 9 code lengths, at 36 + 20 + 81.
  b = bytes;
  b[7] = 10;
  put32(b, 8, 1025);
  put32(b, 12, 1025);
  put32(b, 16, 1025);
  b[20] = 4;
  put32(b, 32, crc32(std::string_view(b).substr(0, 32)));
  put32(b, 40, 67305665);
  put32(b, 44, 67305665);
  EXPECT_EQ(errorOf(b), "offset 137: page table: expected 807667984 bytes, the stream ends after " +
                            std::to_string(b.size() - 137));
  // More stored pages than the grid has.
  b = bytes;
  put32(b, 44, static_cast<std::uint32_t>(layout.pageCount() + 1));
  EXPECT_NE(errorOf(b).find("offset 44: stored_pages: expected 1.." + std::to_string(layout.pageCount())),
            std::string::npos)
      << errorOf(b);
}

// The page table lists exactly the pages that hold a point of the volume, ascending: a stream
// that lacks one, stores one of padding alone, or lists them out of order is refused, naming it.
TEST_F(LebCorrupt, ThePageTableListsExactlyThePagesOfTheVolume) {
  const LebChannel& c = layout.channels[0];
  ASSERT_GE(c.storedPage.size(), 3u);
  std::string b = bytes;
  put32(b, pageIndicesAt(c) + 4, c.storedPage[0]);  // the second entry repeats the first
  fixCrcs(b);
  EXPECT_NE(errorOf(b).find("stored page: " + std::to_string(c.storedPage[0]) + " does not follow page " +
                            std::to_string(c.storedPage[0])),
            std::string::npos)
      << errorOf(b);
  b = bytes;
  put32(b, pageIndicesAt(c) + 4 * (c.storedPage.size() - 1), static_cast<std::uint32_t>(layout.pageCount()));
  fixCrcs(b);
  EXPECT_NE(errorOf(b).find("is not a page of the grid's " + std::to_string(layout.pageCount())), std::string::npos)
      << errorOf(b);
  // The last stored page renamed to one past it that holds only padding (if there is one), or a
  // stored page renamed to a gap: either way a page of the volume goes missing.
  const HzOrder order(layout.grid);
  std::uint32_t padding = 0;
  for (std::uint32_t p = c.storedPage.back() + 1; p < layout.pageCount() && !padding; ++p)
    if (insidePointsOfPage(order, layout.dims, layout.pageBits, p) == 0) padding = p;
  ASSERT_NE(padding, 0u);
  b = bytes;
  put32(b, pageIndicesAt(c) + 4 * (c.storedPage.size() - 1), padding);
  fixCrcs(b);
  EXPECT_NE(errorOf(b).find("data page " + std::to_string(c.storedPage.back()) +
                            " holds points of the volume, but the stream does not store it"),
            std::string::npos)
      << errorOf(b);
}

// The contract of leb_codec.h: what decodeLeb allocates is known from the header, and follows the
// volume, not the grid: the samples (2 bytes), the gradients (3) and the shells of padding that
// predictions reach (leb_padding.h), one a channel, whose size leb_padding_test.cpp derives by
// brute force.
TEST(LebDecodeMemory, TheBoundComesFromTheHeaderAndFollowsTheVolume) {
  const LebStream thin = parseLebStream(encodeLeb(noise({65, 1, 1}, 8, 3), 8));
  const std::uint64_t shell = LebPadding::shellPoints(thin.grid, thin.dims);
  EXPECT_EQ(lebDecodeMemoryBytes(thin), 2u * 65 + 3u * 65 + 2 * LebPadding::tableBytes(thin.grid, thin.dims));
  EXPECT_LT(shell, 65u * 8);  // of the 65^3 grid's 274560 padding points
  EXPECT_LT(LebPadding::tableBytes(thin.grid, thin.dims), 65u * 8 * 16);
  LebEncodeOptions o;
  o.gradients = false;
  const LebStream cube = parseLebStream(encodeLeb(noise({9, 9, 9}, 16, 4), 16, o));
  EXPECT_EQ(lebDecodeMemoryBytes(cube), 2u * 729);  // an unpadded grid: no shell, no table
  const LebDecoded d = decodeLeb(thin);
  EXPECT_EQ(d.data.data().size(), 65u);
}

// The encoder's bound, from the extents alone: the deltas (4 bytes a value), the coded pages, the
// gradients and the shell; a thin volume costs what its samples cost, not its 1025^3 grid.
TEST(LebEncodeMemory, TheBoundFollowsTheVolume) {
  LebEncodeOptions dataOnly;
  dataOnly.gradients = false;
  // A few MiB (the code's counters of the runs that hold samples): the 1025^3 grid took 2.2 GB.
  EXPECT_LT(lebEncodeMemoryBytes({1025, 1, 1}, dataOnly), std::uint64_t{4} << 20);
  EXPECT_LT(lebEncodeMemoryBytes({1025, 1, 1}), std::uint64_t{4} << 20);
  EXPECT_GE(lebEncodeMemoryBytes({1025, 1, 1}), 16u * 1025 + 3 * 1025);  // deltas of both channels, gradients
  EXPECT_GE(lebEncodeMemoryBytes({256, 256, 128}, dataOnly), 8ull * 256 * 256 * 128);  // deltas, then the stream
  EXPECT_THROW(lebEncodeMemoryBytes({9, 9, 9}, LebEncodeOptions{30, true, 0, {}}), std::invalid_argument);  // page bits
  EXPECT_THROW(lebEncodeMemoryBytes({0, 9, 9}), std::invalid_argument);
}

// Padding for free: a 1025x1x1 volume in its 1025^3 grid stores exactly the pages its samples'
// indices fall in (HzOrder::index of each sample, the closed form, not the walk), and its stream
// is of the order of its data.
TEST(LebCodec, ThinVolumesStoreOnlyThePagesOfTheirSamples) {
  const Volume<std::uint16_t> v = smooth({1025, 1, 1}, 8);
  LebEncodeOptions o;
  o.gradients = false;
  const LebStream s = parseLebStream(encodeLeb(v, 8, o));
  const HzOrder order(s.grid);
  std::vector<std::uint32_t> expected;
  for (int x = 0; x < 1025; ++x) expected.push_back(static_cast<std::uint32_t>(order.index({x, 0, 0}) >> s.pageBits));
  std::sort(expected.begin(), expected.end());
  expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
  EXPECT_EQ(s.channels[0].storedPage, expected);
  EXPECT_EQ(lebStats(s).storedPages, expected.size());
  EXPECT_EQ(lebStats(s).pages, (1025ull * 1025 * 1025 + 4095) / 4096);
  EXPECT_LT(s.bytes.size(), 16u * 1025);  // 1025 bytes of data; 12 bytes of table per stored page
  EXPECT_EQ(decodeLeb(s).data.data(), v.data());
}

// The grid of k = 11 (2049^3 points, the paper's 2048x2048x1920 needs it): a thin volume in it
// round-trips with its gradients, with hierarchical indices past 2^32 (the last sample's), and
// random access refuses the grid, naming why (its memo keys are 32-bit linear indices).
TEST(LebCodec, TheGridOfKElevenRoundTripsAndRandomAccessRefusesIt) {
  const Volume<std::uint16_t> v = smooth({2049, 2, 1}, 8);
  const LebStream s = parseLebStream(encodeLeb(v, 8));
  EXPECT_EQ(s.grid.k, 11);
  EXPECT_GT(HzOrder(s.grid).index({2048, 1, 0}), std::uint64_t{1} << 32);
  const LebDecoded d = decodeLeb(s);
  EXPECT_EQ(d.data.data(), v.data());
  EXPECT_EQ(d.gradients, quantizedGradients(v));
  try {
    LebReader reader(std::make_shared<const LebStream>(s), 1u << 20);
    FAIL() << "a k = 11 stream was accepted for random access";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("takes grids up to k = 10"), std::string::npos) << e.what();
  }
}

TEST(LebCorruptClaims, AVolumeLargerThanItsPayloadIsRefused) {
  // A 5x1x1 constant volume (grid 5^3) whose header then claims 5x5x5: 125 deltas cannot fit in
  // the few bytes of payload, whatever the code.
  LebEncodeOptions o;
  o.gradients = false;
  std::string b = encodeLeb(Volume<std::uint16_t>({5, 1, 1}, 9), 8, o);
  for (int at : {12, 16}) b[static_cast<std::size_t>(at)] = 5;
  const std::uint32_t c = crc32(std::string_view(b).substr(0, 32));
  for (int i = 0; i < 4; ++i) b[32 + static_cast<std::size_t>(i)] = static_cast<char>((c >> (8 * i)) & 0xff);
  try {
    parseLebStream(b);
    FAIL();
  } catch (const StreamError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot hold the 125 deltas of a 5x5x5 volume (at least one bit each)"),
              std::string::npos)
        << e.what();
  }
}

// The adaptive coder's bound (kAdaptiveDeltasPerByteBound): a 1x1x1 stream whose header then
// claims 1025^3 (its one page table entry made to fit) holds 5 bytes of page for 1.08 G deltas.
TEST(LebCorruptClaims, AnAdaptiveVolumeLargerThanItsPayloadIsRefused) {
  LebEncodeOptions o;
  o.gradients = false;
  o.coder = LebCoder::Adaptive;
  std::string b = encodeLeb(Volume<std::uint16_t>({1, 1, 1}, 9), 8, o);
  auto put32 = [&](std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xff);
  };
  b[7] = 10;
  for (std::size_t at : {8, 12, 16}) put32(at, 1025);
  put32(32, crc32(std::string_view(b).substr(0, 32)));
  put32(kLebHeaderBytes + 4, lebPageCount(LebGrid{10}, 12));  // page_count (its CRC comes later)
  try {
    parseLebStream(b);
    FAIL();
  } catch (const StreamError& e) {
    EXPECT_NE(std::string(e.what()).find("bytes cannot hold the 1076890625 deltas of a 1025x1025x1025 volume (at "
                                         "least 2^-14 bytes each)"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(LebCorrupt, APageLengthPastTheEnd) {
  std::string b = bytes;
  const LebChannel& c = layout.channels[0];
  put32(b, pageLengthsAt(c), 0x7fffffff);
  fixCrcs(b);
  const std::string e = errorOf(b);
  EXPECT_NE(e.find("page length: page 0 ends at byte 2147483647 of the payload, past its end"), std::string::npos) << e;
}

TEST_F(LebCorrupt, ACodeTableThatIsNotPrefixFree) {
  std::string b = bytes;
  const LebChannel& c = layout.channels[0];
  for (std::size_t s = 0; s < 9; ++s) b[tableAt(c) + s] = 1;
  fixCrcs(b);
  const std::string e = errorOf(b);
  EXPECT_NE(e.find("code lengths: context 0: the code lengths are not those of a prefix-free code"), std::string::npos)
      << e;
}

TEST_F(LebCorrupt, ASymbolPastTheTable) {
  // Context 0 keeps one code, "0", for symbol 0; the first page then starts with a 1 bit.
  std::string b = bytes;
  const LebChannel& c = layout.channels[0];
  for (std::size_t s = 0; s < 9; ++s) b[tableAt(c) + s] = s == 0 ? 1 : 0;
  b[c.payloadOffset] = static_cast<char>(0xff);
  fixCrcs(b);
  const std::string e = errorOf(b);
  EXPECT_NE(e.find("data page 0: value 0: "), std::string::npos) << e;
  EXPECT_NE(e.find("the next 1 bits match no code of context 0"), std::string::npos) << e;
}

TEST_F(LebCorrupt, ChecksumsCatchFlippedBits) {
  std::string b = bytes;
  b[layout.channels[0].payloadOffset + 1] ^= 0x10;
  EXPECT_NE(errorOf(b).find("data page 0: CRC-32 mismatch (the page is corrupt)"), std::string::npos);
  b = bytes;
  b[9] ^= 1;
  EXPECT_EQ(errorOf(b), "offset 32: header_crc: CRC-32 mismatch (the header is corrupt)");
  b = bytes;
  b[tableAt(layout.channels[1]) + 3] ^= 1;
  EXPECT_NE(errorOf(b).find("descriptor crc: CRC-32 mismatch (channel 1's descriptor is corrupt)"), std::string::npos);
}

// Single-byte changes everywhere. Without repaired checksums every one must be reported; with
// repaired ones the decoder must throw StreamError or decode some volume (a changed raw bit of a
// delta is a valid stream), never fail in any other way.
void expectEveryChangeCaught(const std::string& bytes, const std::function<void(std::string&)>& fixCrcs) {
  std::mt19937 rng(4);
  for (int trial = 0; trial < 3000; ++trial) {
    std::string b = bytes;
    const std::size_t at = rng() % b.size();
    b[at] = static_cast<char>(b[at] ^ static_cast<char>(1 + rng() % 255));
    if (trial % 2) fixCrcs(b);
    try {
      const LebDecoded d = decodeLeb(parseLebStream(b));
      if (!(trial % 2)) ADD_FAILURE() << "a change at byte " << at << " passed every checksum";
      (void)d;
    } catch (const StreamError&) {
    } catch (const std::exception& e) {
      ADD_FAILURE() << "byte " << at << ": not a StreamError: " << e.what();
    }
  }
}

TEST_F(LebCorrupt, EveryChangeIsCaughtByAChecksumAndNoneCrashesTheDecoder) {
  expectEveryChangeCaught(bytes, [&](std::string& b) { fixCrcs(b); });
}

class LebCorruptAdaptive : public LebCorrupt {
 protected:
  LebCoder coder() const override { return LebCoder::Adaptive; }
};

TEST_F(LebCorruptAdaptive, TheIntactStreamDecodes) { EXPECT_EQ(errorOf(bytes), ""); }

TEST_F(LebCorruptAdaptive, EveryChangeIsCaughtByAChecksumAndNoneCrashesTheDecoder) {
  expectEveryChangeCaught(bytes, [&](std::string& b) { fixCrcs(b); });
}

// Header bytes 4-5 and 22 (reference/leb/FORMAT.md, section 1): each version has its coder.
TEST_F(LebCorruptAdaptive, TheVersionAndTheCoderAgree) {
  // The stream with byte `at` set to `value`, its checksums made again.
  auto errorWith = [&](std::size_t at, char value) {
    std::string b = bytes;
    b[at] = value;
    fixCrcs(b);
    return errorOf(b);
  };
  EXPECT_EQ(errorWith(22, 0), "offset 22: coder: a version 3 stream has coder 1 (adaptive), got 0");
  EXPECT_EQ(errorWith(4, 2), "offset 22: coder: a version 2 stream has coder 0 (lead-1), got 1");
  EXPECT_EQ(errorWith(4, 4), "offset 22: coder: a version 4 stream has coder 2 (context), got 1");
  EXPECT_EQ(errorWith(4, 5), "offset 4: version: expected 2 (lead-1), 3 (adaptive) or 4 (context), got 5");
  EXPECT_EQ(errorWith(23, 2), "offset 23: gradients: expected 0..1, got 2");  // derived_gradients_test.cpp has 1
}

// A page cut short inside its values (length and CRCs made to agree): the adaptive reader names
// the page.
TEST_F(LebCorruptAdaptive, AShortenedPageIsAStreamErrorNamingIt) {
  const LebChannel& c = layout.channels[0];
  ASSERT_GE(c.pageOffset[1], 6u);
  std::string b = bytes;
  // The first page's last byte becomes the second page's first: the length table moves, the
  // bytes stay; both pages' CRC-32s and the descriptor's are made again for the new boundary.
  const std::uint64_t cut = c.pageOffset[1] - 1;
  put32(b, pageLengthsAt(c), static_cast<std::uint32_t>(cut));
  put32(b, pageLengthsAt(c) + 4, static_cast<std::uint32_t>(c.pageOffset[2] - cut));
  const std::size_t crcs = c.descriptorOffset + c.descriptorBytes - 4 - 4 * c.storedPage.size();
  put32(b, crcs, crc32(std::string_view(b).substr(c.payloadOffset, cut)));
  put32(b, crcs + 4, crc32(std::string_view(b).substr(c.payloadOffset + cut, c.pageOffset[2] - cut)));
  put32(b, c.descriptorOffset + c.descriptorBytes - 4,
        crc32(std::string_view(b).substr(c.descriptorOffset, c.descriptorBytes - 4)));
  const std::string e = errorOf(b);
  EXPECT_NE(e.find("data page "), std::string::npos) << e;
  EXPECT_EQ(e.find("CRC-32"), std::string::npos) << e;
  EXPECT_TRUE(e.find("the page ends inside value") != std::string::npos ||
              e.find("the first byte of an adaptive page must be 0") != std::string::npos)
      << e;
}

}  // namespace
}  // namespace voxref::ref
