#include "conformance/io/leb_file.h"

#include <regex>

#include <gtest/gtest.h>

#include "conformance/io/raw_volume.h"
#include "reference/leb/gradients.h"
#include "reference/leb/leb_codec.h"
#include "tests/scratch_folder.h"

namespace voxref::io {
namespace {

TEST(LebFile, EverySharedVolumeRoundTripsLosslessly) {
  const std::filesystem::path dir = VOXREF_SHARED_VOLUMES;
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " is missing";
  const std::regex name(R"(([a-z_]+)_(\d+)x(\d+)x(\d+)_uint8\.raw\.gz)");
  const test::ScratchFolder scratch;
  int volumes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (!std::regex_match(file, m, name)) continue;
    SCOPED_TRACE(file);
    const ref::Dims3 dims{std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4])};
    const ref::Volume<std::uint8_t> v8 = readRawVolumeU8(entry.path(), dims);
    const ref::Volume<std::uint16_t> v(dims, std::vector<std::uint16_t>(v8.data().begin(), v8.data().end()));
    const auto path = scratch / (m[1].str() + ".vxleb");
    writeLebFile(path, ref::encodeLeb(v, 8));
    const ref::LebDecoded d = ref::decodeLeb(readLebFile(path));
    EXPECT_EQ(d.data.data(), v.data());
    EXPECT_EQ(d.gradients, ref::quantizedGradients(v));
    ++volumes;
  }
  EXPECT_GE(volumes, 4) << "engine, hydrogen_atom, nucleon and bucky are expected in " << dir;
}

TEST(LebFile, ErrorsNameTheFile) {
  const test::ScratchFolder scratch;
  try {
    readLebFile(scratch / "none.vxleb");
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("none.vxleb does not exist"), std::string::npos);
  }
  const auto bad = scratch / "bad.vxleb";
  writeFileAtomically(bad, "VXLB but far too short");
  try {
    readLebFile(bad);
    FAIL();
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.vxleb: offset 4: header: expected 32 bytes"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace voxref::io
