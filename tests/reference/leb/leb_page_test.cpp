#include "reference/leb/leb_page.h"

#include <array>
#include <string>

#include <gtest/gtest.h>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/leb/leb_codec.h"
#include "tests/reference/leb/leb_test_volumes.h"

namespace voxref::ref {
namespace {

using test_support::smooth;

LebStream smoothStream(const Dims3& dims, int pageBits, LebCoder coder) {
  LebEncodeOptions o;
  o.pageBits = pageBits;
  o.coder = coder;
  return parseLebStream(encodeLeb(smooth(dims, 8), 8, o));
}

// What the two calls give, the data page's first; an error as its message.
struct PageOutcome {
  std::array<DecodedPage, 2> pages;
  std::string error;
  bool operator==(const PageOutcome&) const = default;
};
PageOutcome decodeEachAlone(const LebStream& s, const HzOrder& order, std::uint64_t page) {
  PageOutcome o;
  try {
    o.pages[0] = decodePagePositions(s, *s.channel(LebChannelKind::Data), order, page);
    o.pages[1] = decodePagePositions(s, *s.channel(LebChannelKind::Gradients), order, page);
  } catch (const StreamError& e) {
    return {{}, e.what()};
  }
  return o;
}
PageOutcome decodeTogether(const LebStream& s, const HzOrder& order, std::uint64_t page) {
  try {
    return {decodeChannelPagesPositions(s, order, page), ""};
  } catch (const StreamError& e) {
    return {{}, e.what()};
  }
}

TEST(LebPage, BothChannelsDecodeTogetherAsEachAlone) {
  for (const LebCoder coder : test_support::kLebCoders)
    for (const Dims3 dims : {Dims3{37, 5, 101}, Dims3{33, 33, 33}}) {
      SCOPED_TRACE(std::string(lebCoderName(coder)) + " " + dimsText(dims));
      const LebStream s = smoothStream(dims, 8, coder);
      const HzOrder order(s.grid);
      std::uint64_t stored = 0;
      for (std::uint64_t page = 0; page < s.pageCount(); ++page) {
        const PageOutcome alone = decodeEachAlone(s, order, page);
        stored += alone.error.empty() ? 1 : 0;
        ASSERT_EQ(decodeTogether(s, order, page), alone) << "page " << page;
      }
      // Pages of the volume decode (in the thin volume, pages with padding among them), pages of
      // padding alone are refused by both, with the same message.
      EXPECT_EQ(stored, s.channels[0].storedPage.size());
      if (dims[1] == 5) {
        EXPECT_LT(stored, s.pageCount());
      }
    }
}

TEST(LebPage, AStreamWithoutBothChannelsIsRefused) {
  LebEncodeOptions o;
  o.gradients = false;
  const LebStream s = parseLebStream(encodeLeb(smooth({9, 7, 5}, 8), 8, o));
  EXPECT_THROW(decodeChannelPagesPositions(s, HzOrder(s.grid), 0), std::invalid_argument);
}

// A damaged page, in one channel or both, gives the error of the two calls: the data page's
// first, whichever step finds it (the CRC-32 when the page is opened, a value, the page's end).
TEST(LebPage, TheDataPagesErrorComesFirst) {
  enum class Damage { None, Byte, ByteWithItsCrc, Zeros, Ones };
  const Damage damages[] = {Damage::None, Damage::Byte, Damage::ByteWithItsCrc, Damage::Zeros, Damage::Ones};
  for (const LebCoder coder : test_support::kLebCoders) {
    const LebStream intact = smoothStream({9, 7, 5}, 6, coder);
    const HzOrder order(intact.grid);
    const std::string bytes(intact.bytes);
    int errors = 0, differentErrors = 0;
    for (std::uint64_t page = 0; page < intact.pageCount(); ++page) {
      if (intact.channels[0].slotOf(page) < 0) continue;
      for (const Damage dd : damages)
        for (const Damage dg : damages) {
          SCOPED_TRACE(std::string(lebCoderName(coder)) + ", page " + std::to_string(page) + ", damage " +
                       std::to_string(static_cast<int>(dd)) + " / " + std::to_string(static_cast<int>(dg)));
          std::string b = bytes;
          std::array<std::uint32_t, 2> crcs{};
          const std::array<Damage, 2> damage{dd, dg};
          for (std::size_t c = 0; c < 2; ++c) {
            const LebChannel& ch = intact.channels[c];
            const auto slot = static_cast<std::size_t>(ch.slotOf(page));
            const std::size_t at = ch.payloadOffset + ch.pageOffset[slot],
                              size = ch.pageOffset[slot + 1] - ch.pageOffset[slot];
            if (damage[c] == Damage::Byte || damage[c] == Damage::ByteWithItsCrc) b[at + size / 2] ^= 0x5a;
            if (damage[c] == Damage::Zeros || damage[c] == Damage::Ones)
              b.replace(at, size, size, damage[c] == Damage::Zeros ? '\0' : '\xff');
            crcs[c] = damage[c] == Damage::Byte ? ch.pageCrc[slot] : crc32(std::string_view(b).substr(at, size));
          }
          LebStream s = parseLebStream(std::move(b));
          for (std::size_t c = 0; c < 2; ++c)
            s.channels[c].pageCrc[static_cast<std::size_t>(s.channels[c].slotOf(page))] = crcs[c];
          const PageOutcome alone = decodeEachAlone(s, order, page);
          ASSERT_EQ(decodeTogether(s, order, page), alone);
          if (!alone.error.empty()) {
            ++errors;
            differentErrors += alone.error.find("data page") == std::string::npos ? 1 : 0;
          }
        }
    }
    // Damage reached the errors of both channels' pages.
    EXPECT_GT(errors, 0);
    EXPECT_GT(differentErrors, 0);
  }
}

}  // namespace
}  // namespace voxref::ref
