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
#include "tests/reference/leb/mirror_test_volumes.h"

namespace voxref::ref {
namespace {

using test_support::noise;
using test_support::smooth;

// `v` made a mirror image of itself on `planes`, then `differing` of its mirrored points moved off
// their image by +1 (every 97th mirrored point in order, so they spread over the volume).
Volume<std::uint16_t> nearlyMirrored(Volume<std::uint16_t> v, const LebMirrorPlanes& planes, int bits, int differing) {
  v = test_support::mirrored(std::move(v), planes);
  const Dims3 d = v.dims();
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

LebEncodeOptions options(LebCoder coder, LebMirrorGradients gradients, int threads = 0) {
  LebEncodeOptions o;
  o.coder = coder;
  o.pageBits = 6;
  o.gradients = gradients != LebMirrorGradients::None;
  o.deriveGradients = gradients == LebMirrorGradients::Derived;
  o.threads = threads;
  return o;
}
const char* gradientsName(LebMirrorGradients g) {
  return g == LebMirrorGradients::None ? "no gradients" : g == LebMirrorGradients::Derived ? "derived" : "stored";
}

// The gradients a mirrored stream stores in these tests: the volume's own made to mirror with
// `planes`, then every 211th component moved by 3, so that some points differ in their gradient
// alone (a kept point's move moves it off its mirrored points too).
std::vector<std::int8_t> storedGradients(const Volume<std::uint16_t>& v, const LebMirrorPlanes& planes) {
  std::vector<std::int8_t> g = test_support::mirroredGradients(quantizedGradients(v), v.dims(), planes);
  for (std::size_t i = 0; i < g.size(); i += 211) g[i] = static_cast<std::int8_t>(g[i] + 3);
  return g;
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
      for (LebMirrorGradients mode :
           {LebMirrorGradients::None, LebMirrorGradients::Derived, LebMirrorGradients::Stored}) {
        SCOPED_TRACE(c.what + ", " + std::string(lebCoderName(coder)) + ", " + gradientsName(mode));
        const bool derive = mode != LebMirrorGradients::None;  // the reader gives gradients
        const std::vector<std::int8_t> stored =
            mode == LebMirrorGradients::Stored ? storedGradients(c.volume, c.planes) : std::vector<std::int8_t>{};
        const std::string bytes = encodeMirroredLeb(c.volume, c.bits, c.planes, options(coder, mode), stored);
        EXPECT_EQ(bytes, encodeMirroredLeb(c.volume, c.bits, c.planes, options(coder, mode, 1), stored));
        auto stream = std::make_shared<const MirroredLebStream>(parseMirroredLebStream(bytes));
        EXPECT_EQ(stream->header.gradients, mode);
        // Stored, the points off their mirrored gradient are exceptions too: counted here from the
        // definition (a component negated across each plane the point is mirrored on).
        std::size_t expected = c.exceptions;
        if (!stored.empty()) {
          expected = 0;
          const Dims3& d = c.volume.dims();
          for (int z = 0; z < d[2]; ++z)
            for (int y = 0; y < d[1]; ++y)
              for (int x = 0; x < d[0]; ++x) {
                const int p[3] = {x, y, z};
                int q[3];
                for (int a = 0; a < 3; ++a) q[a] = lebMirrorImage(p[a], c.planes.sum[a]);
                const std::size_t i = c.volume.index(x, y, z), j = c.volume.index(q[0], q[1], q[2]);
                bool off = i != j && c.volume.data()[i] != c.volume.data()[j];
                for (int a = 0; a < 3; ++a) {
                  const int image = stored[3 * j + a], own = stored[3 * i + a];
                  off = off || (i != j && own != (q[a] != p[a] ? test_support::negatedComponent(image) : image));
                }
                expected += off;
              }
          ASSERT_GT(expected, c.exceptions);
        }
        EXPECT_EQ(stream->exceptions.size(), expected);
        EXPECT_EQ(stream->inner.dims, lebFoldedDims(c.volume.dims(), c.planes));
        EXPECT_EQ(stream->inner.coder, coder);
        const LebDecoded d = decodeMirroredLeb(*stream, 2);
        EXPECT_EQ(d.data.data(), c.volume.data());
        if (mode == LebMirrorGradients::Derived) {
          EXPECT_EQ(d.gradients, quantizedGradients(c.volume));
        } else if (mode == LebMirrorGradients::Stored) {
          EXPECT_EQ(d.gradients, stored);
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

TEST(MirrorStream, NoPlaneAndGradientsOfAnotherSizeAreRefused) {
  const Case c = cases()[0];
  EXPECT_THROW(encodeMirroredLeb(c.volume, 8, {}, options(LebCoder::Lead1, LebMirrorGradients::None)),
               std::invalid_argument);
  EXPECT_THROW(encodeMirroredLeb(c.volume, 8, c.planes, options(LebCoder::Lead1, LebMirrorGradients::Stored),
                                 std::vector<std::int8_t>(5)),
               std::invalid_argument);
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
  const std::string good =
      encodeMirroredLeb(c.volume, 8, c.planes, options(LebCoder::Context, LebMirrorGradients::None));
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

TEST(MirrorStream, StoredGradientsAreRefusedWhereTheHeaderSaysOtherwise) {
  const Case c = cases()[0];
  const LebEncodeOptions stored = options(LebCoder::Context, LebMirrorGradients::Stored);
  const std::string good = encodeMirroredLeb(c.volume, 8, c.planes, stored, storedGradients(c.volume, c.planes));
  ASSERT_EQ(errorOf(good), "");
  const std::string dataOnly =
      encodeMirroredLeb(c.volume, 8, c.planes, options(LebCoder::Context, LebMirrorGradients::None));
  // Header byte 7: 3 means nothing; 0 (none) before a folded stream with gradients, 2 (stored)
  // before one without. (Flipped from 2 to 0, the exceptions read as data residuals alone: they
  // are refused first when they differ in their gradients only.)
  EXPECT_EQ(errorOf(withHeaderField(good, 7, 3, 1)), "offset 7: gradients: expected 0..2, got 3");
  EXPECT_EQ(errorOf(withHeaderField(dataOnly, 7, 2, 1)).rfind("offset 76: exceptions: ", 0), 0u);
  const std::string exact = encodeMirroredLeb(nearlyMirrored(smooth({21, 18, 23}, 8), c.planes, 8, 0), 8, c.planes,
                                              options(LebCoder::Context, LebMirrorGradients::None));
  EXPECT_EQ(errorOf(withHeaderField(exact, 7, 2, 1)),
            "offset 76: folded stream: expected the data and the gradients channels (header byte 7 says the gradients "
            "are stored)");
  // The count within one in 16 mirrored points (not one in 256: a stored gradient differs more often).
  const MirroredLebStream parsed = parseMirroredLebStream(good);
  const std::uint64_t cap = lebMirroredPoints(c.volume.dims(), c.planes) / kLebMirrorGradientExceptionShare;
  EXPECT_EQ(lebMirrorExceptionCap(c.volume.dims(), c.planes, true), cap);
  EXPECT_EQ(errorOf(withHeaderField(good, 44, cap + 1, 8)),
            "offset 44: exception_count: expected 0.." + std::to_string(cap) + ", got " + std::to_string(cap + 1));
  EXPECT_EQ(errorOf(withHeaderField(good, 44, parsed.exceptions.size() + 1, 8)).rfind("offset 76: exceptions: ", 0),
            0u);
  // The encoder refuses exceptions that are none, and gradient residuals in a stream without them.
  const Dims3 f = lebFoldedDims(c.volume.dims(), c.planes);
  const std::vector<std::uint16_t> folded(sampleCount(f));
  const std::vector<std::int8_t> foldedGradients(3 * sampleCount(f));
  const std::uint64_t mirrored = c.volume.index(20, 0, 0);
  auto encodeWith = [&](const LebMirrorException& e, const LebEncodeOptions& o) {
    encodeMirroredLebTo({f, 8, nullptr, folded.data(), foldedGradients.data()},
                        {c.volume.dims(), 8, c.planes, LebMirrorGradients::None}, {e}, o,
                        [](std::uint64_t, std::string_view) {});
  };
  EXPECT_NO_THROW(encodeWith({mirrored, 0, {0, 1, 0}}, stored));
  try {
    encodeWith({mirrored, 0, {0, 0, 0}}, stored);
    ADD_FAILURE() << "an exception equal to its image";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("its sample and gradient equal their image's"), std::string::npos) << e.what();
  }
  EXPECT_THROW(encodeWith({mirrored, 1, {0, 1, 0}}, options(LebCoder::Context, LebMirrorGradients::Derived)),
               std::invalid_argument);
}

}  // namespace
}  // namespace voxref::ref
