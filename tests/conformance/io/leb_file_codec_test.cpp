#include "conformance/io/leb_file_codec.h"

#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "conformance/io/atomic_file.h"
#include "reference/leb/gradients.h"
#include "reference/leb/mirror_stream.h"
#include "tests/scratch_folder.h"

namespace voxref::io {
namespace {

// A smooth field plus noise of `bits` bits, and its raw file (uint16 little endian).
ref::Volume<std::uint16_t> volumeOf(const ref::Dims3& d, int bits, const std::filesystem::path& raw) {
  std::mt19937 rng(7);
  ref::Volume<std::uint16_t> v(d);
  const double top = bits == 8 ? 255.0 : 65535.0;
  std::string bytes;
  for (std::size_t i = 0; i < v.data().size(); ++i) {
    const double f = 0.5 * top * (1.0 + std::sin(0.21 * static_cast<double>(i % 97) + 0.013 * static_cast<double>(i)));
    v.data()[i] = static_cast<std::uint16_t>(std::clamp(f + static_cast<double>(rng() % 7) - 3.0, 0.0, top));
    bytes.push_back(static_cast<char>(v.data()[i] & 0xff));
    if (bits == 16) bytes.push_back(static_cast<char>(v.data()[i] >> 8));
  }
  writeFileAtomically(raw, bytes);
  return v;
}

// Volumes that fill their grid and that do not (padding on every axis), at 8 and 16 bits; the
// streaming encoder must write the very stream encodeLeb makes in memory, under any window.
struct Case {
  ref::Dims3 dims;
  int bits;
};
class LebFileCodec : public ::testing::TestWithParam<Case> {};

TEST_P(LebFileCodec, EncodesTheStreamEncodeLebMakesAndDecodesItBack) {
  const Case c = GetParam();
  const std::string name = ref::dimsText(c.dims) + "_" + std::to_string(c.bits);
  const test::ScratchFolder dir;
  const auto raw = dir / (name + ".raw"), stream = dir / (name + ".vxleb"), back = dir / (name + ".back.raw"),
             grads = dir / (name + ".grad");
  const ref::Volume<std::uint16_t> v = volumeOf(c.dims, c.bits, raw);
  const VoxelType type = c.bits == 8 ? VoxelType::UInt8 : VoxelType::UInt16;
  const std::string expected = ref::encodeLeb(v, c.bits);
  for (const std::uint64_t window : {kLebWindowBytes, std::uint64_t{1}}) {  // a window of one byte trims every batch
    SCOPED_TRACE(window);
    const LebFileRun enc = encodeLebFile(raw, c.dims, type, stream, ref::LebEncodeOptions{}, window);
    EXPECT_EQ(readWholeFile(stream), expected);
    EXPECT_EQ(enc.streamBytes, expected.size());
    EXPECT_EQ(enc.trims > 0, window == 1);
    const LebFileRun dec = decodeLebFile(openLebFile(stream), back, grads, 0, window);
    EXPECT_EQ(readWholeFile(back), readWholeFile(raw));
    const std::vector<std::int8_t> g = ref::quantizedGradients(v);
    EXPECT_EQ(readWholeFile(grads), std::string(g.begin(), g.end()));
    EXPECT_EQ(dec.trims > 0, window == 1);
  }
  // A stream that derives its gradients: the stream encodeLeb makes with the option, and the same
  // gradients from the decoder, computed only when asked for.
  ref::LebEncodeOptions derive;
  derive.deriveGradients = true;
  const std::string derived = ref::encodeLeb(v, c.bits, derive);
  for (const std::uint64_t window : {kLebWindowBytes, std::uint64_t{1}}) {
    SCOPED_TRACE(window);
    encodeLebFile(raw, c.dims, type, stream, derive, window);
    EXPECT_EQ(readWholeFile(stream), derived);
    std::filesystem::remove(grads);
    decodeLebFile(openLebFile(stream), back, {}, 0, window);
    EXPECT_EQ(readWholeFile(back), readWholeFile(raw));
    EXPECT_FALSE(std::filesystem::exists(grads));
    decodeLebFile(openLebFile(stream), back, grads, 0, window);
    const std::vector<std::int8_t> g = ref::quantizedGradients(v);
    EXPECT_EQ(readWholeFile(grads), std::string(g.begin(), g.end()));
  }
  for (const auto& p : std::filesystem::directory_iterator(raw.parent_path()))
    EXPECT_EQ(p.path().filename().string().find(".tmp"), std::string::npos) << p.path() << " was left behind";
}

// A mirrored stream (reference/leb/mirror_stream.h) between files: the stream encodeMirroredLeb
// makes in memory across the planes findLebMirrorPlanes finds, under any window, decoded back in
// place with its derived or stored gradients.
TEST(LebFileCodecMirrored, EncodesTheStreamEncodeMirroredLebMakesAndDecodesItBack) {
  struct Mirrored {
    ref::Dims3 dims;
    int bits;
    ref::LebMirrorPlanes planes;
    ref::Dims3 off;  // a mirrored point, moved off its image
  };
  for (const Mirrored& c : {Mirrored{{37, 21, 13}, 8, {{36, ref::kNoLebMirror, 11}}, {36, 20, 12}},
                            Mirrored{{20, 9, 17}, 16, {{ref::kNoLebMirror, 8, ref::kNoLebMirror}}, {19, 7, 16}}}) {
    const std::string name = ref::dimsText(c.dims) + "_" + std::to_string(c.bits);
    SCOPED_TRACE(name);
    const test::ScratchFolder dir;
    const auto raw = dir / (name + ".raw"), stream = dir / (name + ".vxleb"), back = dir / (name + ".back.raw"),
               grads = dir / (name + ".grad");
    ref::Volume<std::uint16_t> v = volumeOf(c.dims, c.bits, raw);
    std::string bytes;  // made its own mirror image, one point off it
    for (int z = 0; z < c.dims[2]; ++z)
      for (int y = 0; y < c.dims[1]; ++y)
        for (int x = 0; x < c.dims[0]; ++x) {
          std::uint16_t& s = v.at(x, y, z);
          s = v.at(ref::lebMirrorImage(x, c.planes.sum[0]), ref::lebMirrorImage(y, c.planes.sum[1]),
                   ref::lebMirrorImage(z, c.planes.sum[2]));
          if (ref::Dims3{x, y, z} == c.off) s = static_cast<std::uint16_t>(s ^ 1);
          bytes.push_back(static_cast<char>(s & 0xff));
          if (c.bits == 16) bytes.push_back(static_cast<char>(s >> 8));
        }
    writeFileAtomically(raw, bytes);
    const VoxelType type = c.bits == 8 ? VoxelType::UInt8 : VoxelType::UInt16;
    const std::vector<std::int8_t> g = ref::quantizedGradients(v);
    for (const bool stored : {false, true}) {
      SCOPED_TRACE(stored ? "stored gradients" : "derived gradients");
      ref::LebEncodeOptions o;
      o.deriveGradients = !stored;
      // Stored gradients are folded too, so the planes found are those they fit: the central ones
      // (s = n - 1). Off the centre a slice's central differences face one-sided ones, more
      // exceptions than the search allows.
      ref::LebMirrorPlanes found = c.planes;
      for (int a = 0; a < 3; ++a)
        if (stored && found.sum[a] != c.dims[a] - 1) found.sum[a] = ref::kNoLebMirror;
      ASSERT_TRUE(found.any());
      EXPECT_EQ(ref::findLebMirrorPlanes(v.data().data(), stored ? g.data() : nullptr, c.dims), found);
      const std::string expected = ref::encodeMirroredLeb(v, c.bits, found, o);
      for (const std::uint64_t window : {kLebWindowBytes, std::uint64_t{1}}) {
        SCOPED_TRACE(window);
        for (const LebFileMirror& mirror : {LebFileMirror{true, {}}, LebFileMirror{false, found}}) {
          const LebFileRun enc = encodeLebFile(raw, c.dims, type, stream, o, window, {}, mirror);
          EXPECT_EQ(enc.mirrorPlanes, found);
          EXPECT_EQ(readWholeFile(stream), expected);
          EXPECT_EQ(enc.mirrorExceptions, ref::parseMirroredLebStream(expected).exceptions.size());
        }
        const auto file = openAnyLebFile(stream);
        ASSERT_TRUE(std::holds_alternative<MirroredLebFile>(file));
        decodeLebFile(std::get<MirroredLebFile>(file), back, grads, 0, window);
        EXPECT_EQ(readWholeFile(back), bytes);
        EXPECT_EQ(readWholeFile(grads), std::string(g.begin(), g.end()));
        std::filesystem::remove(grads);  // a stored channel is decoded (and checked) when not asked for too
        decodeLebFile(std::get<MirroredLebFile>(file), back, {}, 0, window);
        EXPECT_EQ(readWholeFile(back), bytes);
        EXPECT_FALSE(std::filesystem::exists(grads));
      }
    }
    try {
      openLebFile(stream);
      ADD_FAILURE() << "openLebFile read a mirrored stream";
    } catch (const FormatError& e) {
      EXPECT_NE(std::string(e.what()).find("offset 0: magic: 'VXLM', a mirrored stream"), std::string::npos);
    }
    for (const auto& p : std::filesystem::directory_iterator(raw.parent_path()))
      EXPECT_EQ(p.path().filename().string().find(".tmp"), std::string::npos) << p.path() << " was left behind";
  }
}

INSTANTIATE_TEST_SUITE_P(Volumes, LebFileCodec,
                         ::testing::Values(Case{{33, 33, 33}, 8}, Case{{37, 21, 13}, 8}, Case{{20, 9, 17}, 16},
                                           Case{{1025, 1, 1}, 8}));

TEST(LebFileCodecErrors, NameTheFileAndLeaveNothing) {
  const test::ScratchFolder dir;
  const auto raw = dir / "err.raw", stream = dir / "err.vxleb";
  volumeOf({16, 16, 16}, 8, raw);
  std::filesystem::remove(stream);
  try {
    encodeLebFile(raw, {16, 16, 17}, VoxelType::UInt8, stream, {});
    ADD_FAILURE() << "a file of the wrong size was encoded";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("holds 4096 bytes; the dimensions need 4352"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(stream));
  ref::LebEncodeOptions dataOnly;
  dataOnly.gradients = false;
  encodeLebFile(raw, {16, 16, 16}, VoxelType::UInt8, stream, dataOnly);
  EXPECT_THROW(decodeLebFile(openLebFile(stream), dir / "err.back", dir / "err.grad"), std::invalid_argument);
  encodeLebFile(raw, {16, 16, 16}, VoxelType::UInt8, stream, {});
  bool refused = false;
  try {
    decodeLebFile(openLebFile(stream), dir / "same", dir / "same");
  } catch (const IoError& e) {
    refused = std::string(e.what()).find("two outputs name the same file") != std::string::npos;
  }
  EXPECT_TRUE(refused);
  EXPECT_FALSE(std::filesystem::exists(dir / "err.back"));
}

}  // namespace
}  // namespace voxref::io
