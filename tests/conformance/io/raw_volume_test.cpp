#include "conformance/io/raw_volume.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "conformance/io/atomic_file.h"
#include "tests/scratch_folder.h"

namespace voxref::io {
namespace {

class RawVolume : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& bytes, bool gzip) {
    const auto p = dir_ / name;
    if (gzip) {
      gzFile f = gzopen(p.c_str(), "wb");
      gzwrite(f, bytes.data(), static_cast<unsigned>(bytes.size()));
      gzclose(f);
    } else {
      std::ofstream(p, std::ios::binary) << bytes;
    }
    return p;
  }
  const test::ScratchFolder dir_;
};

// The reader grows its buffer with what it has read (64 KiB, then doubling): volumes across
// those steps read back exactly, plain and gzip, 8 and 16 bits.
TEST_F(RawVolume, ReadsVolumesAcrossTheBufferSteps) {
  for (const ref::Dims3 dims :
       {ref::Dims3{4, 3, 2}, ref::Dims3{64, 32, 32}, ref::Dims3{256, 256, 3}, ref::Dims3{97, 89, 71}}) {
    std::string bytes(ref::sampleCount(dims) * 2, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7 + i / 251);
    for (bool gz : {false, true}) {
      const auto p = write(gz ? "v.raw.gz" : "v.raw", bytes, gz);
      const ref::Volume<std::uint16_t> v16 = readRawVolumeU16(p, dims);
      ASSERT_EQ(v16.data().size(), ref::sampleCount(dims));
      EXPECT_EQ(v16.data().back(), static_cast<std::uint16_t>(static_cast<unsigned char>(bytes[bytes.size() - 2]) |
                                                              (static_cast<unsigned char>(bytes.back()) << 8)));
      const std::string half = bytes.substr(0, bytes.size() / 2);
      const ref::Volume<std::uint8_t> v8 = readRawVolumeU8(write(gz ? "h.raw.gz" : "h.raw", half, gz), dims);
      EXPECT_EQ(std::string(v8.data().begin(), v8.data().end()), half);
    }
  }
}

// Found by tests/fuzz/raw_volume_fuzz.cpp (tests/fuzz/regressions/raw_volume/
// claimed_size_allocates_16MiB): a 1-byte file said to be 256^3 voxels made the reader allocate
// (and zero) 16 MiB before reading it; the error is unchanged, the allocation now follows the file.
TEST_F(RawVolume, ClaimedSizeLargerThanTheFileIsAClearError) {
  const auto p = write("one.raw", "\x7f", false);
  try {
    (void)readRawVolumeU8(p, {256, 256, 256});
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("holds 1 bytes; the dimensions need 16777216"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)readRawVolumeU16(write("more.raw", std::string(20, 'x'), false), {3, 3, 1}), IoError);
}

// The contract of raw_volume.h ("Memory: ..."): dimensions are checked, and claims larger than the
// data are refused by what the file holds, never by allocating them; a gzip stream must be whole.
TEST_F(RawVolume, HugeDimensionsAreRefusedNamingTheFile) {
  const auto p = write("small.raw", std::string(4096, 'v'), false);
  auto errorOf = [&](const ref::Dims3& dims) {
    try {
      (void)readRawVolumeU8(p, dims);
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(
      errorOf({65535, 65535, 65535}),
      "volume file " + p.string() +
          ": the dimensions are out of range: volume of 65535x65535x65535 samples exceeds the limit of 1099511627776");
  EXPECT_EQ(errorOf({0, 16, 16}),
            "volume file " + p.string() + ": the dimensions are out of range: volume extent 0 is not positive");
  EXPECT_EQ(errorOf({10000, 10000, 10000}),
            "volume file " + p.string() + " holds 4096 bytes; the dimensions need 1000000000000");
}

TEST_F(RawVolume, AGzipThatExpandsBeyondTheDimensionsIsRefused) {
  const auto p = write("bomb.raw.gz", std::string(std::size_t{64} << 20, '\0'), true);  // 64 MiB of zeros in 64 KiB
  try {
    (void)readRawVolumeU8(p, {16, 16, 16});
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()),
              "volume file " + p.string() + " holds more than 4096 bytes; the dimensions need 4096");
  }
}

// zlib's gzread returns a short read without an error when a small file ends inside the gzip
// trailer, so its CRC-32 was never checked: the reader inflates itself and wants the trailer.
TEST_F(RawVolume, AGzipStreamMustBeWholeAndItsChecksumMustMatch) {
  std::string data(4096, '\0');
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<char>(i * 13 + i / 7);
  const auto whole = write("whole.raw.gz", data, true);
  std::ifstream in(whole, std::ios::binary);
  const std::string gz((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto errorOf = [&](const std::string& bytes, ref::Dims3 dims = {16, 16, 16}) {
    const auto p = write("bad.raw.gz", bytes, false);
    try {
      (void)readRawVolumeU8(p, dims);
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(errorOf(gz), "");
  for (std::size_t cut : {4, 8, 20}) {
    const std::string e = errorOf(gz.substr(0, gz.size() - cut));
    EXPECT_NE(e.find("is a truncated gzip stream: the file ends after "), std::string::npos)
        << "cut " << cut << ": " << e;
  }
  std::string flipped = gz;
  flipped[gz.size() - 8] = static_cast<char>(~flipped[gz.size() - 8]);  // the trailer's CRC-32
  EXPECT_NE(errorOf(flipped).find("incorrect data check (the CRC-32 in the gzip trailer does not match the data)"),
            std::string::npos)
      << errorOf(flipped);
  EXPECT_NE(errorOf(gz + "garbage").find("is corrupt at byte"), std::string::npos);
  EXPECT_EQ(errorOf(gz + gz, {16, 16, 32}), "");  // gzip members one after the other are one stream
  EXPECT_NE(errorOf(gz + gz.substr(0, gz.size() - 8), {16, 16, 32}).find("is a truncated gzip stream"),
            std::string::npos);
}

TEST_F(RawVolume, AFolderIsNotAVolume) {
  try {
    (void)readRawVolumeU8(dir_.path(), {1, 1, 1});
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_EQ(std::string(e.what()), "volume file " + dir_.path().string() + " is not a regular file");
  }
}

}  // namespace
}  // namespace voxref::io
