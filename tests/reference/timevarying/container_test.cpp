#include "reference/timevarying/container.h"

#include <zlib.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "reference/common/byte_stream.h"
#include "reference/timevarying/plume.h"

namespace voxref::ref {
namespace {

TimeVaryingFile sampleFile(ref::IndexEncoding e = ref::IndexEncoding::NormalizedRgba8) {
  const ref::TimeSeries s = ref::dischargePlume({32, 5, 400.0});
  TimeVaryingFile f;
  f.transfer = ref::transferFunction("plume");
  ref::TimeVaryingOptions o{2, e};
  f.textures = ref::encodeTimeVarying(s, f.transfer, o);
  return f;
}

std::string errorOf(std::string_view bytes) {
  try {
    parseTimeVarying(bytes);
  } catch (const StreamError& e) {
    return e.what();
  }
  return "";
}

// Rewrites the trailing CRC so that a deliberately changed field is what the parser meets.
void fixCrc(std::string& b) {
  const uLong c =
      crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(b.data()), static_cast<uInt>(b.size() - 4));
  for (int i = 0; i < 4; ++i) b[b.size() - 4 + i] = static_cast<char>((c >> (8 * i)) & 0xff);
}

TEST(TimeVaryingContainer, RoundTripsEveryEncoding) {
  for (ref::IndexEncoding e : {ref::IndexEncoding::NormalizedRgba8, ref::IndexEncoding::NormalizedRgba16,
                               ref::IndexEncoding::NormalizedFloat, ref::IndexEncoding::BlockRgba8}) {
    const TimeVaryingFile f = sampleFile(e);
    const TimeVaryingFile g = parseTimeVarying(serializeTimeVarying(f));
    EXPECT_EQ(g.textures.index.texels, f.textures.index.texels);
    EXPECT_EQ(g.textures.refinement.texels, f.textures.refinement.texels);
    EXPECT_EQ(g.transfer.table, f.transfer.table);
    EXPECT_EQ(g.textures.stats.refinementBytes, f.textures.stats.refinementBytes);
    for (int t = 0; t < 5; ++t) EXPECT_EQ(ref::decodeStep(g.textures, t), ref::decodeStep(f.textures, t));
  }
}

// Volumes that stress the alpha-one policies: constants (every cell homogeneous, one colour),
// white noise (every cell refined) and smooth blobs (both kinds).
std::vector<std::pair<std::string, ref::TimeSeries>> roundTripSeries(int side) {
  std::vector<std::pair<std::string, ref::TimeSeries>> out;
  auto constant = [&](std::uint8_t v) {
    ref::TimeSeries s;
    s.side = side;
    s.original = {side, side, side};
    s.steps.assign(2, std::vector<std::uint8_t>(static_cast<std::size_t>(side) * side * side, v));
    return s;
  };
  out.emplace_back("constant_255", constant(255));
  out.emplace_back("constant_0", constant(0));
  ref::TimeSeries noise = constant(0);
  std::uint32_t x = 12345;
  for (auto& step : noise.steps)
    for (std::uint8_t& v : step) v = static_cast<std::uint8_t>((x = x * 1664525u + 1013904223u) >> 24);
  out.emplace_back("white_noise", noise);
  out.emplace_back("blobs", ref::driftingBlobs(side, 2));
  return out;
}

// The input after the transfer function: what the refine policy must decode, derived from the
// series alone (not from the codec).
std::vector<ref::Rgba8> inputColours(const ref::TimeSeries& s, const ref::TransferFunction& tf, int t) {
  std::vector<ref::Rgba8> out;
  for (std::uint8_t v : s.steps[static_cast<std::size_t>(t)]) out.push_back(tf(v));
  return out;
}

// Every file the encoder writes is read back exactly: over both alpha-one policies, every index
// encoding, every level, constant, noisy and smooth volumes and three transfer functions, the
// parsed textures equal the written ones and decode to the same voxels; under the refine policy
// those are the input after the transfer function; under the paper's, every voxel whose colour
// does not have alpha 255 still is.
TEST(TimeVaryingContainer, EveryFileTheEncoderWritesReadsBackExactly) {
  const int side = 16;
  std::size_t files = 0;
  for (const auto& [name, series] : roundTripSeries(side))
    for (const char* tfName : {"gray", "opaque", "plume"})
      for (ref::IndexEncoding e : {ref::IndexEncoding::NormalizedRgba8, ref::IndexEncoding::NormalizedRgba16,
                                   ref::IndexEncoding::NormalizedFloat, ref::IndexEncoding::BlockRgba8})
        for (ref::AlphaOnePolicy policy : {ref::AlphaOnePolicy::Paper, ref::AlphaOnePolicy::Refine})
          for (int level = 1; level <= 3; ++level) {
            const std::string what = name + " " + tfName + " " + std::string(ref::name(e)) + " level " +
                                     std::to_string(level) +
                                     (policy == ref::AlphaOnePolicy::Paper ? " paper" : " refine");
            TimeVaryingFile f;
            f.transfer = ref::transferFunction(tfName);
            ref::TimeVaryingOptions o{level, e, policy};
            f.textures = ref::encodeTimeVarying(series, f.transfer, o);
            TimeVaryingFile g;
            try {
              g = parseTimeVarying(serializeTimeVarying(f));
            } catch (const std::exception& ex) {
              ADD_FAILURE() << what << ": the file does not read back: " << ex.what();
              continue;
            }
            ++files;
            EXPECT_EQ(g.textures.alphaOne, policy) << what;
            EXPECT_EQ(g.textures.index.texels, f.textures.index.texels) << what;
            EXPECT_EQ(g.textures.refinement.texels, f.textures.refinement.texels) << what;
            for (int t = 0; t < 2; ++t) {
              const std::vector<ref::Rgba8> decoded = ref::decodeStep(g.textures, t);
              EXPECT_EQ(decoded, ref::decodeStep(f.textures, t)) << what;
              const std::vector<ref::Rgba8> want = inputColours(series, f.transfer, t);
              if (policy == ref::AlphaOnePolicy::Refine) {
                EXPECT_EQ(decoded, want) << what;
                continue;
              }
              for (std::size_t i = 0; i < want.size(); ++i)
                if (want[i][3] != 255 && decoded[i] != want[i]) {
                  ADD_FAILURE() << what << ": voxel " << i << " of step " << t
                                << " has no alpha-one colour and decodes wrongly";
                  break;
                }
            }
          }
  EXPECT_EQ(files, 4u * 3u * 4u * 2u * 3u);
}

// The reported case: a constant-255 volume under the gray transfer function, paper policy. Every
// cell is homogeneous with colour (255, 255, 255, 255), stored as it is; no block is stored, and the
// one block slot of the refinement texture is zero. The paper's decoder reads the colour as the
// address round(255 B / 255) = B = 1 on every axis, past the texture, so CLAMP_TO_EDGE reads its
// last texel: every voxel decodes to (0, 0, 0, 0).
TEST(TimeVaryingContainer, TheFlagCollisionOfAConstantOpaqueVolumeDecodesAsThePapersDecoderReadsIt) {
  const ref::TimeSeries s = roundTripSeries(64).front().second;
  TimeVaryingFile f;
  f.transfer = ref::transferFunction("gray");
  ASSERT_EQ(f.transfer(255), (ref::Rgba8{255, 255, 255, 255}));
  f.textures =
      ref::encodeTimeVarying(s, f.transfer, {1, ref::IndexEncoding::NormalizedRgba8, ref::AlphaOnePolicy::Paper});
  const TimeVaryingFile g = parseTimeVarying(serializeTimeVarying(f));
  EXPECT_EQ(g.textures.stats.distinctBlocks, 0u);
  for (const ref::Rgba8& c : ref::decodeStep(g.textures, 0)) ASSERT_EQ(c, (ref::Rgba8{0, 0, 0, 0}));
}

TEST(TimeVaryingContainer, MoreTimeStepsThanTheFormatHoldsAreRefusedWhenWriting) {
  ref::TimeSeries s;
  s.side = 4;
  s.original = {1, 1, 1};
  s.steps.assign(65537, std::vector<std::uint8_t>(64, 0));
  TimeVaryingFile f;
  f.transfer = ref::transferFunction("gray");
  f.textures = ref::encodeTimeVarying(s, f.transfer, {1});
  try {
    (void)serializeTimeVarying(f);
    ADD_FAILURE() << "65537 time steps were serialized";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("65537 time steps: the .vxtv container holds 1..65536"), std::string::npos)
        << e.what();
  }
}

// `--level auto` keeps the smallest file: its size equals the least of every level's file.
TEST(TimeVaryingContainer, AutoLevelWritesTheSmallestFile) {
  for (const auto& [name, series] : roundTripSeries(64))
    for (const char* tfName : {"plume", "gray"}) {
      TimeVaryingFile f;
      f.transfer = ref::transferFunction(tfName);
      std::size_t smallest = SIZE_MAX;
      int smallestLevel = 0;
      for (int level = 1; level <= 5; ++level) {
        f.textures = ref::encodeTimeVarying(series, f.transfer, {level});
        const std::size_t bytes = serializeTimeVarying(f).size();
        if (bytes < smallest) smallest = bytes, smallestLevel = level;
      }
      f.textures = ref::encodeTimeVaryingAutoLevel(series, f.transfer, {});
      EXPECT_EQ(serializeTimeVarying(f).size(), smallest)
          << name << " " << tfName << ": auto chose level " << f.textures.layout.level << ", level " << smallestLevel
          << " is smallest";
    }
}

TEST(TimeVaryingContainer, TruncatedFilesNameTheOffset) {
  const std::string b = serializeTimeVarying(sampleFile());
  for (std::size_t n : {std::size_t{0}, std::size_t{3}, std::size_t{50}, std::size_t{96}, std::size_t{200},
                        b.size() / 2, b.size() - 1}) {
    const std::string e = errorOf(std::string_view(b).substr(0, n));
    EXPECT_NE(e.find("offset "), std::string::npos) << n << ": " << e;
  }
  EXPECT_NE(errorOf(std::string_view(b).substr(0, b.size() - 1)).find("(truncated)"), std::string::npos);
  EXPECT_NE(errorOf(b + "x").find("(trailing bytes)"), std::string::npos);
}

TEST(TimeVaryingContainer, CorruptionAndBadFieldsAreNamed) {
  const std::string good = serializeTimeVarying(sampleFile());
  std::string b = good;
  b[b.size() / 2] ^= 0x40;
  EXPECT_NE(errorOf(b).find("CRC-32 mismatch"), std::string::npos);
  b = good;
  b[0] = 'X';
  EXPECT_EQ(errorOf(b), "offset 0: magic: expected 'VXTV' (not a .vxtv file)");
  b = good;
  b[4] = 2;
  EXPECT_EQ(errorOf(b), "offset 4: version: expected 1, got 2");
  b = good;
  b[8] = 100;  // side 100
  EXPECT_EQ(errorOf(b), "offset 8: side: expected a power of two, got 100");
  b = good;
  b[48] = 9;
  EXPECT_EQ(errorOf(b), "offset 48: encoding: expected 0..3, got 9");
}

TEST(TimeVaryingContainer, HugeClaimedSizesAreRefusedBeforeAllocating) {
  std::string b = serializeTimeVarying(sampleFile());
  // index_slots = 4096 (x 4 cells = 16384 texels per axis: 17.6 TB of texels claimed).
  b[28] = 0x00;
  b[29] = 0x10;
  const std::string e = errorOf(b);
  EXPECT_NE(e.find("the header describes"), std::string::npos) << e;
  EXPECT_NE(e.find("(truncated)"), std::string::npos) << e;
}

// The contract of container.h ("Memory: ..."): a header whose every field agrees with the others
// (side 512, 65536 steps, level 7: 128^3 cells of 4^3 voxels, 64^3 index slots, 4096^3 block slots,
// every cell homogeneous) claims 2.2 TB of index and 17.6 TB of refinement texture; the 10 KB file
// is refused at the first texture, by its length, before anything is allocated for them.
TEST(TimeVaryingContainer, AHeaderWhoseFieldsAgreeClaimingTerabytesIsRefusedByTheFileLength) {
  std::string b = serializeTimeVarying(sampleFile());
  auto put = [&b](std::size_t at, std::uint64_t v, std::size_t width) {
    for (std::size_t i = 0; i < width; ++i) b[at + i] = static_cast<char>((v >> (8 * i)) & 0xff);
  };
  put(8, 512, 4);
  put(12, 65536, 4);
  put(16, 7, 4);
  put(20, 128, 4);
  put(24, 4, 4);
  put(28, 64, 4);
  put(32, 4096, 4);
  put(56, std::uint64_t{65536} * 128 * 128 * 128, 8);
  put(64, 0, 8);
  const std::size_t texturesAt = 96 + 1 + 5 + 1024;  // the header, the transfer function "plume" and its table
  const std::uint64_t claimed =
      texturesAt + std::uint64_t{8192} * 8192 * 8192 * 4 + std::uint64_t{16384} * 16384 * 16384 * 4 + 4;
  EXPECT_EQ(errorOf(b), "offset " + std::to_string(texturesAt) + ": the header describes " + std::to_string(claimed) +
                            " bytes in all, the file has " + std::to_string(b.size()) + " (truncated)");
}

TEST(TimeVaryingContainer, AnAddressOutsideTheStoredBlocksIsRejected) {
  const TimeVaryingFile f = sampleFile();
  std::string b = serializeTimeVarying(f);
  // Find the first refinement texel in the index payload and point it at the last block slot.
  const std::size_t indexAt = 96 + 1 + f.transfer.name.size() + 1024;
  std::size_t texel = 0;
  while (!ref::isRefinementFlag(f.textures.index.encoding, &f.textures.index.texels[4 * texel])) ++texel;
  for (int a = 0; a < 3; ++a) b[indexAt + 4 * texel + a] = static_cast<char>(255);
  fixCrc(b);
  EXPECT_NE(errorOf(b).find("is not one of the " + std::to_string(f.textures.stats.distinctBlocks) + " blocks"),
            std::string::npos)
      << errorOf(b);
}

}  // namespace
}  // namespace voxref::ref
