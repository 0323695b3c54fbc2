// Streams of the context coder (version 4; reference/leb/context_codec.h, reference/leb/FORMAT.md,
// "Context pages"): round trips through the whole-volume decoder and random access, the same bytes
// for every thread count, and the refusals of streams whose page table or shape is wrong.
#include "reference/leb/context_codec.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/leb/context_value_coder.h"
#include "reference/leb/gradients.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_padding.h"
#include "reference/leb/leb_reader.h"
#include "tests/reference/leb/leb_test_volumes.h"

namespace voxref::ref {
namespace {

using test_support::noise;
using test_support::smooth;

LebEncodeOptions contextOptions(int pageBits, bool derive, int threads = 0) {
  LebEncodeOptions o;
  o.pageBits = pageBits;
  o.coder = LebCoder::Context;
  o.gradients = derive;
  o.deriveGradients = derive;
  o.threads = threads;
  return o;
}

struct ContextCase {
  const char* name;
  Volume<std::uint16_t> volume;
  int bits, pageBits;
};

std::vector<ContextCase> contextCases() {
  return {{"smooth 13x7x9", smooth({13, 7, 9}, 8), 8, 6},
          {"noise 6x5x4", noise({6, 5, 4}, 8, 11), 8, 4},
          {"smooth 16-bit 9^3", smooth({9, 9, 9}, 16), 16, 5},
          {"noise 16-bit 7x3x5", noise({7, 3, 5}, 16, 12), 16, 4},
          {"thin 33x1x1", smooth({33, 1, 1}, 8), 8, 4},
          {"single sample", Volume<std::uint16_t>({1, 1, 1}, 201), 8, 4},
          {"full grid 17^3", smooth({17, 17, 17}, 8), 8, 12},
          {"extremes", noise({5, 5, 5}, 1, 13), 8, 4}};
}

// Every case decodes to its samples, and its derived gradients to quantizedGradients, for one and
// two threads, from the same bytes.
TEST(ContextCodec, EveryVolumeRoundTripsWithTheSameBytesForAnyThreadCount) {
  for (ContextCase& c : contextCases()) {
    if (c.name == std::string("extremes"))
      for (auto& s : c.volume.data()) s = s ? 255 : 0;  // residuals of +-255 around a mean of 0 and 255
    const std::string one = encodeLeb(c.volume, c.bits, contextOptions(c.pageBits, true, 1));
    const std::string two = encodeLeb(c.volume, c.bits, contextOptions(c.pageBits, true, 2));
    ASSERT_EQ(one, two) << c.name;
    const LebStream s = parseLebStream(one);
    EXPECT_EQ(s.coder, LebCoder::Context);
    EXPECT_EQ(s.channels.size(), 1u);
    for (int threads : {1, 2}) {
      const LebDecoded d = decodeLeb(s, threads);
      EXPECT_EQ(d.data.data(), c.volume.data()) << c.name << ", " << threads << " threads";
      EXPECT_EQ(d.gradients, quantizedGradients(c.volume)) << c.name;
    }
  }
}

// Random access at every point of the grid, the last first (pages then decode their corners'
// pages from inside the recursion): r gives the sample and the gradient that p, a reader of the
// paper's lead-1 stream of the same volume and gradients, gives by another path (deltas and split
// edges); inside the volume, its own sample and its vector of `gradients`.
void expectEveryGridPoint(LebReader& r, LebReader& p, const ContextCase& c, const std::vector<std::int8_t>& gradients) {
  const int n = lebGridCovering(c.volume.dims()).pointsPerAxis();
  for (int z = n - 1; z >= 0; --z)
    for (int y = n - 1; y >= 0; --y)
      for (int x = n - 1; x >= 0; --x) {
        const GridPoint q{x, y, z};
        ASSERT_EQ(r.sample(q), p.sample(q)) << c.name << " at " << x << "," << y << "," << z;
        ASSERT_EQ(r.gradient(q), p.gradient(q)) << c.name << " at " << x << "," << y << "," << z;
        if (insideVolume(q, c.volume.dims())) {
          ASSERT_EQ(r.sample(q), c.volume.at(x, y, z)) << c.name;
          const std::size_t i = 3 * volumeIndex(q, c.volume.dims());
          ASSERT_EQ((std::array<std::int8_t, 3>{gradients[i], gradients[i + 1], gradients[i + 2]}), r.gradient(q))
              << c.name;
        }
      }
}

// Random access gives every point of the grid: a sample of the volume its own, a point of the
// padding its split edge's prediction, which the paper's lead-1 stream of the same volume gives by
// another path (deltas and split edges); and the gradients derived from the samples. With a
// cache that keeps no page too, and in reverse order (pages then decode their corners' pages
// from inside the recursion).
TEST(ContextCodec, RandomAccessGivesEveryPointAsTheLead1StreamDoes) {
  for (ContextCase& c : contextCases()) {
    auto context = std::make_shared<const LebStream>(
        parseLebStream(encodeLeb(c.volume, c.bits, contextOptions(c.pageBits, true))));
    LebEncodeOptions lead1;
    lead1.pageBits = c.pageBits;
    auto paper = std::make_shared<const LebStream>(parseLebStream(encodeLeb(c.volume, c.bits, lead1)));
    const std::vector<std::int8_t> gradients = quantizedGradients(c.volume);
    // Without a cache every query decodes its page again: the small volumes only.
    for (std::size_t budget : {std::size_t{0}, std::size_t{1} << 20}) {
      if (budget == 0 && sampleCount(c.volume.dims()) > 512) continue;
      LebReader r(context, budget), p(paper, 1 << 20);
      ASSERT_NO_FATAL_FAILURE(expectEveryGridPoint(r, p, c, gradients));
    }
  }
}

// The waves of the whole-volume decoder: every corner of every point of a page lies in the page
// itself or below the page contextPagesNeededBelow names (the corners found by a search of the
// point's neighbourhood, not by the format's closed form).
TEST(ContextCodec, APageNeedsOnlyThePagesItsWaveFollows) {
  for (const Dims3& dims : {Dims3{17, 17, 17}, Dims3{13, 7, 9}, Dims3{33, 2, 5}})
    for (int pageBits : {4, 6, 9}) {
      const HzOrder order(lebGridCovering(dims));
      std::uint64_t checked = 0;
      order.forEachInside(dims, 0, order.size(), [&](std::uint64_t h, const GridPoint& p, int level, int s, unsigned) {
        if (level < 0) return;
        const std::uint64_t page = h >> pageBits, below = contextPagesNeededBelow(order, pageBits, page);
        const int step = 1 << s;
        for (int dz = -step; dz <= step; dz += step)
          for (int dy = -step; dy <= step; dy += step)
            for (int dx = -step; dx <= step; dx += step) {
              const GridPoint q{p[0] + dx, p[1] + dy, p[2] + dz};
              if (q[0] < 0 || q[1] < 0 || q[2] < 0 || !insideVolume(q, dims)) continue;
              // A corner: coordinates multiples of 2h (reference/leb/FORMAT.md), reached on the odd
              // axes only.
              if (q[0] % (2 * step) || q[1] % (2 * step) || q[2] % (2 * step)) continue;
              const std::uint64_t qp = order.index(q) >> pageBits;
              ASSERT_TRUE(qp == page || qp < below) << "page " << page << " needs page " << qp << ", below " << below
                                                    << " (page bits " << pageBits << ")";
              ++checked;
            }
      });
      EXPECT_GT(checked, 0u);
    }
}

// Stored gradients (reference/leb/FORMAT.md, "Context gradient pages"): the central differences'
// unit vectors, the paper's diffused ones, and arbitrary int8 triples decode to themselves through
// the whole-volume decoder (the same bytes for one and two threads) and through random access,
// where a point of the padding takes its split edge's prediction, as the lead-1 stream storing the
// same gradients gives it.
TEST(ContextCodec, StoredGradientsRoundTripThroughBothDecoders) {
  for (ContextCase& c : contextCases()) {
    std::mt19937 rng(static_cast<unsigned>(sampleCount(c.volume.dims())));
    std::vector<std::int8_t> any(3 * sampleCount(c.volume.dims()));
    for (auto& g : any) g = static_cast<std::int8_t>(rng() % 256);
    for (const std::vector<std::int8_t>& gradients :
         {quantizedGradients(c.volume), diffusedQuantizedGradients(c.volume, 2), any}) {
      const std::vector<std::uint8_t> data8(c.volume.data().begin(), c.volume.data().end());
      const auto encode = [&](LebEncodeOptions o) {
        o.gradients = true;
        o.deriveGradients = false;
        std::string bytes;
        const LebVolumeIn in{c.volume.dims(), c.bits, nullptr, c.volume.data().data(), gradients.data()};
        encodeLebTo(in, o, [&](std::uint64_t at, std::string_view b) {
          if (bytes.size() < at + b.size()) bytes.resize(at + b.size());
          std::copy(b.begin(), b.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at));
        });
        return bytes;
      };
      const std::string one = encode(contextOptions(c.pageBits, false, 1));
      ASSERT_EQ(one, encode(contextOptions(c.pageBits, false, 2))) << c.name;
      auto s = std::make_shared<const LebStream>(parseLebStream(one));
      ASSERT_EQ(s->channels.size(), 2u);
      for (int threads : {1, 2}) {
        const LebDecoded d = decodeLeb(*s, threads);
        EXPECT_EQ(d.data.data(), c.volume.data()) << c.name;
        EXPECT_EQ(d.gradients, gradients) << c.name << ", " << threads << " threads";
      }
      LebEncodeOptions lead1;
      lead1.pageBits = c.pageBits;
      auto paper = std::make_shared<const LebStream>(parseLebStream(encode(lead1)));
      LebReader r(s, std::size_t{1} << 20), p(paper, std::size_t{1} << 20);
      ASSERT_NO_FATAL_FAILURE(expectEveryGridPoint(r, p, c, gradients));
    }
  }
}

// --- Streams assembled by hand: a header, one descriptor, the given pages -------------------------

class ContextStream : public ::testing::Test {
 protected:
  // The pages of a thin padded volume (5x3x1 in a 5^3 grid, pages of 2^4): some of the grid's 8
  // pages hold none of its points.
  void SetUp() override {
    const LebStream s = parseLebStream(encodeLeb(volume, 8, contextOptions(kPageBits, false)));
    const LebChannel& c = s.channels[0];
    for (std::size_t j = 0; j < c.storedPage.size(); ++j)
      pages.emplace_back(c.storedPage[j], std::string(s.page(c, j)));
    ASSERT_GE(pages.size(), 3u);
  }
  std::string assemble(const std::vector<std::pair<std::uint32_t, std::string>>& stored, int channels = 1) const {
    const LebGrid grid = lebGridCovering(volume.dims());
    LebChannelTable t;
    t.coder = LebCoder::Context;
    std::string payload;
    for (const auto& [page, bytes] : stored) {
      t.storedPage.push_back(page);
      t.pageLength.push_back(static_cast<std::uint32_t>(bytes.size()));
      t.pageCrc.push_back(crc32(bytes));
      payload += bytes;
    }
    const std::string descriptor = lebDescriptorBytes(lebPageCount(grid, kPageBits), t);
    const std::uint64_t total = kLebHeaderBytes + descriptor.size() + payload.size();
    return lebHeaderBytes(volume.dims(), 8, grid, kPageBits, channels, total, LebCoder::Context) + descriptor + payload;
  }
  static std::string errorOf(std::string b) { return test_support::lebDecodeError(std::move(b)); }
  static constexpr int kPageBits = 4;
  Volume<std::uint16_t> volume = smooth({5, 3, 1}, 8);
  std::vector<std::pair<std::uint32_t, std::string>> pages;
};

TEST_F(ContextStream, TheAssembledStreamDecodes) {
  EXPECT_EQ(errorOf(assemble(pages)), "");
  EXPECT_EQ(decodeLeb(parseLebStream(assemble(pages))).data.data(), volume.data());
}

TEST_F(ContextStream, APageOfPointsMissingFromTheTableIsNamed) {
  auto without = pages;
  const std::uint32_t dropped = without[1].first;
  without.erase(without.begin() + 1);
  EXPECT_EQ(errorOf(assemble(without)), "offset 36: data page " + std::to_string(dropped) +
                                            " holds points of the volume, but the stream does not store it (the "
                                            "page table lacks it)");
}

TEST_F(ContextStream, AStoredPageWithoutPointsIsNamed) {
  auto extra = pages;
  std::uint32_t empty = 0;  // the first page of padding alone
  while (std::any_of(pages.begin(), pages.end(), [&](const auto& p) { return p.first == empty; })) ++empty;
  extra.emplace_back(empty, extra.back().second);
  std::sort(extra.begin(), extra.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  EXPECT_EQ(errorOf(assemble(extra)), "offset 36: data page " + std::to_string(empty) +
                                          " is stored, but it holds no point of the volume (a stream stores "
                                          "exactly the pages that do)");
}

TEST_F(ContextStream, APageOfAnotherPlaceDoesNotDecodeSilently) {
  // The bytes of page 0 under the index of another stored page: its points and corners differ, so
  // the reader refuses it or decodes other values (never this volume).
  auto swapped = pages;
  std::swap(swapped[0].second, swapped[1].second);
  const std::string e = errorOf(assemble(swapped));
  if (e.empty()) {
    EXPECT_NE(decodeLeb(parseLebStream(assemble(swapped))).data.data(), volume.data());
  } else {
    EXPECT_NE(e.find("data page"), std::string::npos) << e;
  }
}

TEST_F(ContextStream, ACorruptPageIsNamedByItsCrc) {
  auto corrupt = pages;
  std::string b = assemble(corrupt);
  b[b.size() - 2] ^= 0x10;  // the last page's bytes; its CRC in the table stays
  const LebStream s = parseLebStream(assemble(corrupt));
  const LebChannel& c = s.channels[0];
  const std::size_t last = c.payloadOffset + static_cast<std::size_t>(c.pageOffset[c.storedPage.size() - 1]);
  EXPECT_EQ(errorOf(b), "offset " + std::to_string(last) + ": data page " + std::to_string(pages.back().first) +
                            ": CRC-32 mismatch (the page is corrupt)");
}

}  // namespace
}  // namespace voxref::ref
