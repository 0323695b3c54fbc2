// The manifest.json of the isosurface fixtures (iso_fixtures.h) read back from its bytes: the
// generator, every scene's parameters and every file's sha256. `voxref fixtures verify` reads it
// before it regenerates anything; tests/fuzz/fixture_manifest_fuzz.cpp holds it to its contract.
//
// Safe on untrusted input: anything that is not such a manifest throws io::FormatError naming
// the source and what is wrong, never another exception.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/modules/iso/iso_scene.h"

namespace voxref::conf {

struct IsoFixtureFile {
  std::string path;    // relative to the fixture directory: <scene>/frame_NN_{mesh,exact}.exr
  std::string sha256;  // lowercase hex
};

struct IsoFixtureManifest {
  nlohmann::json document;
  std::string generator;
  std::vector<IsoScene> scenes;
  std::vector<IsoFixtureFile> files;
};

// Throws io::FormatError.
IsoFixtureManifest parseIsoFixtureManifest(std::string_view bytes, const std::string& sourceName);

}  // namespace voxref::conf
