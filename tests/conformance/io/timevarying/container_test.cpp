#include "conformance/io/timevarying/container.h"

#include <zlib.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "conformance/io/raw_volume.h"
#include "reference/timevarying/plume.h"

namespace voxref::io {
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
    parseTimeVarying(bytes, "test.vxtv");
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

// Rewrites the trailing CRC so that a deliberately changed field is what the parser meets.
void fixCrc(std::string& b) {
  const uLong c = crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(b.data()), static_cast<uInt>(b.size() - 4));
  for (int i = 0; i < 4; ++i) b[b.size() - 4 + i] = static_cast<char>((c >> (8 * i)) & 0xff);
}

TEST(TimeVaryingContainer, RoundTripsEveryEncoding) {
  for (ref::IndexEncoding e : {ref::IndexEncoding::NormalizedRgba8, ref::IndexEncoding::NormalizedRgba16, ref::IndexEncoding::NormalizedFloat,
                               ref::IndexEncoding::BlockRgba8}) {
    const TimeVaryingFile f = sampleFile(e);
    const TimeVaryingFile g = parseTimeVarying(serializeTimeVarying(f), "x");
    EXPECT_EQ(g.textures.index.texels, f.textures.index.texels);
    EXPECT_EQ(g.textures.refinement.texels, f.textures.refinement.texels);
    EXPECT_EQ(g.transfer.table, f.transfer.table);
    EXPECT_EQ(g.textures.stats.refinementBytes, f.textures.stats.refinementBytes);
    for (int t = 0; t < 5; ++t) EXPECT_EQ(ref::decodeStep(g.textures, t), ref::decodeStep(f.textures, t));
  }
}

TEST(TimeVaryingContainer, TruncatedFilesNameTheOffset) {
  const std::string b = serializeTimeVarying(sampleFile());
  for (std::size_t n : {std::size_t{0}, std::size_t{3}, std::size_t{50}, std::size_t{96}, std::size_t{200}, b.size() / 2, b.size() - 1}) {
    const std::string e = errorOf(std::string_view(b).substr(0, n));
    EXPECT_NE(e.find("test.vxtv: offset "), std::string::npos) << n << ": " << e;
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
  EXPECT_EQ(errorOf(b), "test.vxtv: offset 0: magic: expected 'VXTV' (not a .vxtv file)");
  b = good;
  b[4] = 2;
  EXPECT_EQ(errorOf(b), "test.vxtv: offset 4: version: expected 1, got 2");
  b = good;
  b[8] = 100;  // side 100
  EXPECT_EQ(errorOf(b), "test.vxtv: offset 8: side: expected a power of two, got 100");
  b = good;
  b[48] = 9;
  EXPECT_EQ(errorOf(b), "test.vxtv: offset 48: encoding: expected 0..3, got 9");
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
  const std::uint64_t claimed = texturesAt + std::uint64_t{8192} * 8192 * 8192 * 4 + std::uint64_t{16384} * 16384 * 16384 * 4 + 4;
  EXPECT_EQ(errorOf(b), "test.vxtv: offset " + std::to_string(texturesAt) + ": the header describes " + std::to_string(claimed) +
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
  EXPECT_NE(errorOf(b).find("is not one of the " + std::to_string(f.textures.stats.distinctBlocks) + " blocks"), std::string::npos)
      << errorOf(b);
}

TEST(TimeVaryingContainer, EverySharedVolumeRoundTripsAsOneTimeStep) {
  const std::filesystem::path dir = VOXREF_SHARED_VOLUMES;
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " is missing";
  const std::pair<const char*, ref::Dims3> volumes[] = {{"hydrogen_atom_128x128x128_uint8.raw.gz", {128, 128, 128}},
                                                        {"engine_256x256x128_uint8.raw.gz", {256, 256, 128}},
                                                        {"nucleon_41x41x41_uint8.raw.gz", {41, 41, 41}},
                                                        {"bucky_32x32x32_uint8.raw.gz", {32, 32, 32}}};
  for (const auto& [file, dims] : volumes) {
    const ref::TimeSeries s = ref::padToCube({readRawVolumeU8(dir / file, dims)});
    TimeVaryingFile f;
    f.transfer = ref::transferFunction("gray");
    f.textures = ref::encodeTimeVaryingAutoLevel(s, f.transfer, {});
    const TimeVaryingFile g = parseTimeVarying(serializeTimeVarying(f), file);
    const std::vector<ref::Rgba8> decoded = ref::decodeStep(g.textures, 0);
    ASSERT_EQ(decoded.size(), ref::sampleCount(dims)) << file;
    std::size_t i = 0, wrong = 0;
    for (int z = 0; z < dims[2]; ++z)
      for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x, ++i)
          wrong += decoded[i] != f.transfer(s.steps[0][static_cast<std::size_t>(x) + static_cast<std::size_t>(s.side) * (y + static_cast<std::size_t>(s.side) * z)]);
    EXPECT_EQ(wrong, 0u) << file;
  }
}

}  // namespace
}  // namespace voxref::io
