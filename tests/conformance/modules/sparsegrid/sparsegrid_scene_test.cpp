#include "conformance/modules/sparsegrid/sparsegrid_scene.h"

#include <gtest/gtest.h>

#include "conformance/io/atomic_file.h"
#include "conformance/modules/sparsegrid/sparsegrid_catalog.h"
#include "tests/scratch_folder.h"

namespace voxref::conf {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseSparseGridScene(nlohmann::json::parse(text));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(SparseGridScene, RoundTripsThroughJson) {
  SparseGridScene s = defaultSparseGridScene();
  s.grid.level = 9;
  s.textures.format = ref::TexelFormat::R16F;
  s.sampler.wrap = ref::Wrap::ClampToBorder;
  s.sampler.borderRed = 0.25;
  s.framebuffer = ref::FramebufferFormat::RGBA16F;
  s.shading.mode = ref::RenderMode::Iso;
  s.camera.origin = glm::dvec3(0.0);
  s.camera.dx = glm::dvec3(0.125, 0, 0);
  s.camera.dy = glm::dvec3(0, 0.125, 0);
  s.camera.dz = glm::dvec3(0, 0, 0.125);
  s.passOrder = {2, 0, 1};
  EXPECT_EQ(toJson(parseSparseGridScene(toJson(s))), toJson(s));
}

TEST(SparseGridScene, ErrorsNameTheFieldAndWhatWasExpected) {
  EXPECT_EQ(errorOf(R"({"level": 13})"), "level: 13 is outside 1..12");
  EXPECT_EQ(errorOf(R"({"level": 0})"), "level: 0 is outside 1..12");
  EXPECT_EQ(errorOf(R"({"level": "six"})"), "level: expected an integer, got \"six\"");
  EXPECT_EQ(errorOf(R"({"framebuffer": "rgb565"})"),
            "framebuffer: 'rgb565' is not one of rgba8, rgba12, rgba16, rgba16f, rgba32f");
  EXPECT_EQ(errorOf(R"({"texture": {"fromat": "r8"}})"), "texture.fromat: unknown key");
  EXPECT_EQ(errorOf(R"({"data": {"field": "nope"}})").rfind("data.field: unknown analytic field 'nope'", 0), 0u);
  EXPECT_EQ(errorOf(R"({"image": [0, 10]})"), "image: expected [width, height] within 1..4096");
  EXPECT_EQ(errorOf(R"({"system": "leb"})"), "system: 'leb' is not 'sparsegrid'");
  EXPECT_EQ(errorOf(R"([1, 2])"), "the document: expected an object, got [1,2]");
}

// Found by tests/fuzz/scene_json_fuzz.cpp (tests/fuzz/regressions/scene_json/
// sparsegrid_image_float_overflows_int): integers were converted by nlohmann without a check, a
// float beyond int's range being undefined behaviour and 2^32 + 64 silently becoming 64.
TEST(SparseGridScene, IntegersAreCheckedBeforeTheyAreConverted) {
  EXPECT_EQ(errorOf(R"({"image": [-1e300, 5]})"), "image: expected an array of integers, got [-1e+300,5]");
  EXPECT_EQ(errorOf(R"({"image": [48.5, 48]})"), "image: expected an array of integers, got [48.5,48]");
  EXPECT_EQ(errorOf(R"({"pass_order": [1e300]})"), "pass_order: expected an array of integers, got [1e+300]");
  EXPECT_EQ(errorOf(R"({"planes": 4294967360})"), "planes: expected an integer, got 4294967360");
  EXPECT_EQ(errorOf(R"({"data": {"volume": "v.raw", "dims": [9, 9, -1e300]}})"),
            "data.dims: expected an array of integers, got [9,9,-1e+300]");
  EXPECT_EQ(errorOf(R"({"planes": 64, "image": [64, 64]})"), "");
}

TEST(SparseGridScene, CameraMustBeFloat32Exact) {
  SparseGridScene s = defaultSparseGridScene();
  s.camera.origin = glm::dvec3(0.1);  // not on the 2^-22 lattice
  s.camera.dx = glm::dvec3(0.125, 0, 0);
  s.camera.dy = glm::dvec3(0, 0.125, 0);
  s.camera.dz = glm::dvec3(0, 0, 0.125);
  EXPECT_THROW(makeFrame(s), SceneError);
}

TEST(SparseGridScene, PlaneKeyIgnoresOnlyTheShading) {
  SparseGridScene a = defaultSparseGridScene(), b = a;
  b.shading.mode = ref::RenderMode::Iso;
  b.shading.isovalue = 0.7;
  EXPECT_EQ(planeKey(a), planeKey(b));
  b.framebuffer = ref::FramebufferFormat::RGBA16;
  EXPECT_NE(planeKey(a), planeKey(b));
}

TEST(LoadField, VolumeWithWrongSizeOrMissingFileIsAClearError) {
  const test::ScratchFolder dir;
  io::writeFileAtomically(dir / "tiny.raw", std::string(27, '\x10'));
  DataSource d;
  d.volume = dir / "tiny.raw";
  d.volumeDims = {3, 3, 3};
  EXPECT_EQ(loadField(d)(0.5, 0.5, 0.5), 16.0 / 255.0);
  d.volumeDims = {4, 3, 3};
  try {
    loadField(d);
    FAIL();
  } catch (const io::IoError& e) {
    EXPECT_NE(std::string(e.what()).find("holds 27 bytes; the dimensions need 36"), std::string::npos) << e.what();
  }
  d.volume = dir / "missing.raw";
  EXPECT_THROW(loadField(d), io::IoError);
}

}  // namespace
}  // namespace voxref::conf
