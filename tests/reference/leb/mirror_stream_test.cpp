// Mirrored LEB streams (reference/leb/mirror_stream.h, mirror_reader.h; reference/leb/FORMAT.md,
// "Mirrored streams"): every coder's folded stream decodes, whole and point by point, to the volume
// it was made from; the gradients are those of the unfolded samples (quantizedGradients of the
// original volume); and the parser refuses what the format forbids, naming the offset.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/leb/gradients.h"
#include "reference/leb/mirror_reader.h"
#include "reference/leb/mirror_stream.h"
#include "tests/reference/leb/leb_test_volumes.h"

namespace voxref::ref {
namespace {

using test_support::noise;
using test_support::smooth;

// `v` made a mirror image of itself on `planes`, then `differing` of its mirrored points moved off
// their image by +1 (every 97th mirrored point in order, so they spread over the volume).
Volume<std::uint16_t> nearlyMirrored(Volume<std::uint16_t> v, const LebMirrorPlanes& planes, int bits, int differing) {
  const Dims3 d = v.dims();
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x)
        v.at(x, y, z) =
            v.at(lebMirrorImage(x, planes.sum[0]), lebMirrorImage(y, planes.sum[1]), lebMirrorImage(z, planes.sum[2]));
  int seen = 0;
  for (int z = 0; z < d[2] && differing > 0; ++z)
    for (int y = 0; y < d[1] && differing > 0; ++y)
      for (int x = 0; x < d[0] && differing > 0; ++x)
        if ((lebMirroredCoordinate(x, planes.sum[0]) || lebMirroredCoordinate(y, planes.sum[1]) ||
             lebMirroredCoordinate(z, planes.sum[2])) &&
            seen++ % 97 == 0) {
          v.at(x, y, z) = static_cast<std::uint16_t>((v.at(x, y, z) + 1) & ((1u << bits) - 1));
          --differing;
        }
  return v;
}

LebEncodeOptions options(LebCoder coder, bool derive, int threads = 0) {
  LebEncodeOptions o;
  o.coder = coder;
  o.pageBits = 6;
  o.gradients = derive;
  o.deriveGradients = derive;
  o.threads = threads;
  return o;
}

struct Case {
  std::string what;
  Volume<std::uint16_t> volume;
  LebMirrorPlanes planes;
  int bits;
  std::size_t exceptions;
};

std::vector<Case> cases() {
  return {{"three planes, smooth, 8-bit",
           nearlyMirrored(smooth({21, 18, 23}, 8), {{20, 15, 24}}, 8, 5),
           {{20, 15, 24}},
           8,
           5},
          {"one plane, noise, 16-bit",
           nearlyMirrored(noise({17, 9, 12}, 16, 4), {{16, kNoLebMirror, kNoLebMirror}}, 16, 3),
           {{16, kNoLebMirror, kNoLebMirror}},
           16,
           3},
          {"exact, thin",
           nearlyMirrored(noise({1, 1, 40}, 8, 2), {{kNoLebMirror, kNoLebMirror, 39}}, 8, 0),
           {{kNoLebMirror, kNoLebMirror, 39}},
           8,
           0}};
}

TEST(MirrorStream, EveryCodersStreamDecodesWholeAndPointByPointToTheVolume) {
  for (const Case& c : cases())
    for (LebCoder coder : {LebCoder::Lead1, LebCoder::Adaptive, LebCoder::Context})
      for (bool derive : {false, true}) {
        SCOPED_TRACE(c.what + ", " + std::string(lebCoderName(coder)) + (derive ? ", derived gradients" : ""));
        const std::string bytes = encodeMirroredLeb(c.volume, c.bits, c.planes, options(coder, derive));
        EXPECT_EQ(bytes, encodeMirroredLeb(c.volume, c.bits, c.planes, options(coder, derive, 1)));
        auto stream = std::make_shared<const MirroredLebStream>(parseMirroredLebStream(bytes));
        EXPECT_EQ(stream->exceptions.size(), c.exceptions);
        EXPECT_EQ(stream->inner.dims, lebFoldedDims(c.volume.dims(), c.planes));
        EXPECT_EQ(stream->inner.coder, coder);
        const LebDecoded d = decodeMirroredLeb(*stream, 2);
        EXPECT_EQ(d.data.data(), c.volume.data());
        if (derive) {
          EXPECT_EQ(d.gradients, quantizedGradients(c.volume));
        } else {
          EXPECT_TRUE(d.gradients.empty());
        }
        MirroredLebReader reader(stream, 1 << 20);
        const Dims3& dims = c.volume.dims();
        std::size_t wrong = 0;
        for (int z = dims[2] - 1; z >= 0; --z)  // backwards: ancestors are not all reconstructed first
          for (int y = dims[1] - 1; y >= 0; --y)
            for (int x = dims[0] - 1; x >= 0; --x) {
              wrong += reader.sample({x, y, z}) != c.volume.at(x, y, z);
              if (derive) {
                const std::array<std::int8_t, 3> g = reader.gradient({x, y, z});
                wrong += !std::equal(g.begin(), g.end(), d.gradients.begin() + 3 * c.volume.index(x, y, z));
              }
            }
        EXPECT_EQ(wrong, 0u);
        EXPECT_THROW(reader.sample({dims[0], 0, 0}), std::invalid_argument);
        if (!derive) {
          EXPECT_THROW(reader.gradient({0, 0, 0}), std::invalid_argument);
        }
      }
}

TEST(MirrorStream, StoredGradientsAndNoPlaneAreRefused) {
  const Case c = cases()[0];
  LebEncodeOptions stored = options(LebCoder::Lead1, false);
  stored.gradients = true;
  EXPECT_THROW(encodeMirroredLeb(c.volume, 8, c.planes, stored), std::invalid_argument);
  EXPECT_THROW(encodeMirroredLeb(c.volume, 8, {}, options(LebCoder::Lead1, false)), std::invalid_argument);
}

// The StreamError of parsing and decoding a whole stream, or "".
std::string errorOf(std::string bytes) {
  try {
    decodeMirroredLeb(parseMirroredLebStream(std::move(bytes)));
  } catch (const StreamError& e) {
    return e.what();
  }
  return "";
}

// Sets the header field at `at` and mends the header's CRC.
std::string withHeaderField(std::string b, std::size_t at, std::uint64_t v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) b[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
  const std::uint32_t crc = crc32(std::string_view(b).substr(0, 72));
  for (std::size_t i = 0; i < 4; ++i) b[72 + i] = static_cast<char>((crc >> (8 * i)) & 0xff);
  return b;
}

TEST(MirrorStream, CorruptStreamsAreRefusedWithTheirOffset) {
  const Case c = cases()[0];
  const std::string good = encodeMirroredLeb(c.volume, 8, c.planes, options(LebCoder::Context, false));
  ASSERT_EQ(errorOf(good), "");
  const MirroredLebStream parsed = parseMirroredLebStream(good);
  const std::size_t inner = parsed.innerOffset;
  std::string b = good;
  b[10] ^= 1;
  EXPECT_EQ(errorOf(b), "offset 72: header_crc: CRC-32 mismatch (the header is corrupt)");
  EXPECT_EQ(errorOf(good.substr(0, 50)), "offset 4: header: expected 72 bytes, the stream ends after 46");
  EXPECT_EQ(errorOf(good.substr(0, good.size() - 1)).rfind("offset 60: total_bytes:", 0), 0u);
  b = good;
  b[kLebMirrorHeaderBytes] ^= 4;
  EXPECT_EQ(errorOf(b), "offset 68: exceptions_crc: CRC-32 mismatch (the exceptions are corrupt)");
  // One exception more than the bytes hold.
  EXPECT_EQ(errorOf(withHeaderField(good, 44, c.exceptions + 1, 8)).rfind("offset 76: exceptions: ", 0), 0u);
  // A sum that mirrors nothing; then one that keeps a point an exception names.
  EXPECT_EQ(errorOf(withHeaderField(good, 20, 41, 8)),
            "offset 20: mirror_sum: x: expected -1 (none) or 1..39 for an extent of 21, got 41");
  EXPECT_NE(errorOf(withHeaderField(good, 20, 39, 8)).find("is kept, not mirrored"), std::string::npos);
  // No plane at all.
  std::string none = withHeaderField(good, 20, ~std::uint64_t{0}, 8);
  none = withHeaderField(none, 28, ~std::uint64_t{0}, 8);
  EXPECT_EQ(errorOf(withHeaderField(none, 36, ~std::uint64_t{0}, 8)),
            "offset 20: mirror_sum: no axis is mirrored (a mirrored stream folds one at least)");
  // The folded stream's own faults carry offsets in the whole stream.
  b = good;
  b[inner] ^= 1;
  EXPECT_EQ(errorOf(b),
            "offset " + std::to_string(inner) + ": folded stream: magic: expected 'VXLB' (not an LEB stream)");
  b = good;
  b[b.size() - 3] ^= 0x10;  // in the last page's bytes or the descriptor after it
  const std::string e = errorOf(b);
  ASSERT_EQ(e.rfind("offset ", 0), 0u) << e;
  EXPECT_GE(std::stoull(e.substr(7)), inner) << e;
  EXPECT_NE(e.find("folded stream: "), std::string::npos) << e;
}

}  // namespace
}  // namespace voxref::ref
