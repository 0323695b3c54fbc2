#include "conformance/modules/iso/iso_manifest.h"

#include <gtest/gtest.h>

#include "conformance/io/atomic_file.h"
#include "conformance/modules/iso/iso_fixtures.h"

namespace voxref::conf {
namespace {

nlohmann::json manifestOf(const std::vector<IsoScene>& scenes) {
  nlohmann::json m{
      {"generator", kFixtureGenerator}, {"scenes", nlohmann::json::array()}, {"files", nlohmann::json::array()}};
  for (const IsoScene& s : scenes) {
    m["scenes"].push_back(toJson(s));
    m["files"].push_back({{"path", s.name + "/frame_00_mesh.exr"}, {"sha256", std::string(64, 'a')}});
  }
  return m;
}

std::string errorOf(const nlohmann::json& m) {
  try {
    (void)parseIsoFixtureManifest(m.dump(), "manifest.json");
  } catch (const io::FormatError& e) {
    return e.what();
  }
  return "";
}

TEST(IsoManifest, ReadsWhatTheGeneratorWrites) {
  const IsoFixtureManifest m = parseIsoFixtureManifest(manifestOf(hardIsoScenes()).dump(2), "manifest.json");
  EXPECT_EQ(m.generator, kFixtureGenerator);
  ASSERT_EQ(m.scenes.size(), hardIsoScenes().size());
  for (std::size_t i = 0; i < m.scenes.size(); ++i) EXPECT_EQ(toJson(m.scenes[i]), toJson(hardIsoScenes()[i]));
  EXPECT_EQ(m.files.front().path, m.scenes.front().name + "/frame_00_mesh.exr");
}

TEST(IsoManifest, ErrorsAreFormatErrorsNamingTheField) {
  const nlohmann::json good = manifestOf(builtInIsoScenes());
  EXPECT_NE(errorOf(nlohmann::json::array()).find("manifest.json: expected a JSON object"), std::string::npos);
  nlohmann::json m = good;
  m["generator"] = 3;
  EXPECT_NE(errorOf(m).find("generator: expected a string"),
            std::string::npos);  // was nlohmann's type_error, after regenerating
  m = good;
  m["files"][0]["path"] = "../../etc/passwd";
  EXPECT_NE(errorOf(m).find("files[0].path: '../../etc/passwd' is not a relative path inside the fixture directory"),
            std::string::npos);
  m["files"][0]["path"] = "/tmp/x";
  EXPECT_NE(errorOf(m).find("files[0].path"), std::string::npos);
  m = good;
  m["files"][0]["sha256"] = "ABC";
  EXPECT_NE(errorOf(m).find("files[0].sha256: expected 64 lowercase hexadecimal digits"), std::string::npos);
  m = good;
  m["scenes"][1].erase("isovalue");
  EXPECT_NE(errorOf(m).find("scenes[1].isovalue: missing"), std::string::npos) << errorOf(m);
  // Unknown keys are refused, as in the other scene readers (json_reader.h).
  m = good;
  m["scenes"][0]["colour"] = "red";
  EXPECT_NE(errorOf(m).find("scenes[0].colour: unknown key"), std::string::npos) << errorOf(m);
  m = good;
  m["scenes"][0]["camera"]["zoom"] = 2;
  EXPECT_NE(errorOf(m).find("scenes[0].camera.zoom: unknown key"), std::string::npos) << errorOf(m);
}

// Found by tests/fuzz/fixture_manifest_fuzz.cpp (tests/fuzz/regressions/fixture_manifest and
// scene_json).
TEST(IsoManifest, FuzzRegressions) {
  const nlohmann::json good = manifestOf(builtInIsoScenes());
  // empty_scene_name: files are written under <dir>/<name>: "", "..", "a/b" or "/tmp" escape it.
  for (const char* name : {"", ".", "..", "a/b", "/tmp"}) {
    nlohmann::json m = good;
    m["scenes"][0]["name"] = name;
    EXPECT_NE(errorOf(m).find("scenes[0].name: '" + std::string(name) + "' is not a plain file name"),
              std::string::npos)
        << name;
  }
  // iso_dims_float_overflows_int (scene_json): get<int>() of 1e300 was undefined behaviour.
  nlohmann::json m = good;
  m["scenes"][0]["dims"] = {65, 65, 1e300};
  EXPECT_NE(errorOf(m).find("scenes[0].dims[2]: expected an integer, got 1e+300"), std::string::npos);
  m["scenes"][0]["dims"] = {65, 65, 2000};
  EXPECT_NE(errorOf(m).find("scenes[0].dims[2]: 2000 is outside 1..1025"), std::string::npos);
  m["scenes"][0]["dims"] = {65, 65};
  EXPECT_NE(errorOf(m).find("scenes[0].dims: expected 3 integers"), std::string::npos);
  m = good;
  m["scenes"][0]["orbit"]["frames"] = -1;
  EXPECT_NE(errorOf(m).find("scenes[0].orbit.frames: -1 is outside 1..10000"), std::string::npos);
  m = good;
  m["scenes"][0]["refinement"]["max_splits"] = -1.5;
  EXPECT_NE(errorOf(m).find("scenes[0].refinement.max_splits: expected an integer"), std::string::npos);
}

// single_voxel_outside_small_volume, plateau_isovalue_overflows_uint16: isoSceneVolume wrote
// outside a small volume and converted an isovalue beyond uint16 (undefined behaviour).
TEST(IsoSceneVolume, RefusesDataItCannotBuild) {
  IsoScene s = hardIsoScenes().front();
  ASSERT_EQ(s.data, "single_voxel");
  s.dims = {12, 12, 6};
  EXPECT_THROW((void)isoSceneVolume(s), std::invalid_argument);
  s.dims = {3, 4, 7};
  const ref::Volume<std::uint16_t> v = isoSceneVolume(s);
  EXPECT_EQ(v.at(2, 0, 6), 200);
  s.data = "plateau";
  s.dims = {12, 12, 12};
  s.isovalue = 1e10;
  EXPECT_THROW((void)isoSceneVolume(s), std::invalid_argument);
  s.isovalue = -1.0;
  EXPECT_THROW((void)isoSceneVolume(s), std::invalid_argument);
  s.isovalue = 120.0;
  EXPECT_EQ(isoSceneVolume(s).at(3, 4, 3), 120);
}

}  // namespace
}  // namespace voxref::conf
