#include "conformance/io/timevarying_file.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "conformance/io/raw_volume.h"
#include "reference/timevarying/plume.h"
#include "tests/scratch_folder.h"

namespace voxref::io {
namespace {

// Errors of a file name the file, then the container's offset and field.
TEST(TimeVaryingFile, ErrorsNameTheFileThenTheOffset) {
  const test::ScratchFolder dir;
  ref::TimeVaryingFile f;
  f.transfer = ref::transferFunction("plume");
  f.textures = ref::encodeTimeVarying(ref::dischargePlume({16, 2, 400.0}), f.transfer, {2});
  writeTimeVarying(dir / "good.vxtv", f);
  EXPECT_EQ(readTimeVarying(dir / "good.vxtv").textures.index.texels, f.textures.index.texels);
  std::ofstream(dir / "bad.vxtv", std::ios::binary) << "VXTX";
  try {
    (void)readTimeVarying(dir / "bad.vxtv");
    ADD_FAILURE() << "read a file that is not a container";
  } catch (const FormatError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "bad.vxtv").string() + ": offset 0: magic: expected 'VXTV' (not a .vxtv file)");
  }
}

TEST(TimeVaryingFile, EverySharedVolumeRoundTripsAsOneTimeStep) {
  const std::filesystem::path dir = VOXREF_SHARED_VOLUMES;
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " is missing";
  const std::pair<const char*, ref::Dims3> volumes[] = {{"hydrogen_atom_128x128x128_uint8.raw.gz", {128, 128, 128}},
                                                        {"engine_256x256x128_uint8.raw.gz", {256, 256, 128}},
                                                        {"nucleon_41x41x41_uint8.raw.gz", {41, 41, 41}},
                                                        {"bucky_32x32x32_uint8.raw.gz", {32, 32, 32}}};
  for (const auto& [file, dims] : volumes) {
    const ref::TimeSeries s = ref::padToCube({readRawVolumeU8(dir / file, dims)});
    ref::TimeVaryingFile f;
    f.transfer = ref::transferFunction("gray");
    f.textures = ref::encodeTimeVaryingAutoLevel(s, f.transfer, {});
    const ref::TimeVaryingFile g = ref::parseTimeVarying(ref::serializeTimeVarying(f));
    const std::vector<ref::Rgba8> decoded = ref::decodeStep(g.textures, 0);
    ASSERT_EQ(decoded.size(), ref::sampleCount(dims)) << file;
    std::size_t i = 0, wrong = 0;
    for (int z = 0; z < dims[2]; ++z)
      for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x, ++i)
          wrong += decoded[i] !=
                   f.transfer(s.steps[0][static_cast<std::size_t>(x) + static_cast<std::size_t>(s.side) *
                                                                           (y + static_cast<std::size_t>(s.side) * z)]);
    EXPECT_EQ(wrong, 0u) << file;
  }
}

}  // namespace
}  // namespace voxref::io
