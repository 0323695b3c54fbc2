// voxref fixtures generate | verify: the Embree ground truth of the isosurface system
// (conformance/modules/iso/iso_fixtures.h) for the built-in scenes or the user's own volume.
#include <algorithm>
#include <iostream>

#include "conformance/cli/commands.h"
#include "conformance/modules/iso/iso_fixtures.h"
#include "conformance/framework/runner.h"

namespace voxref::cli {
namespace {

std::vector<conf::IsoScene> requestedScenes(const FixturesOptions& o) {
  std::vector<conf::IsoScene> scenes;
  if (!o.volume.empty()) {
    if (o.dims.size() != 3) throw conf::UsageError("--volume needs --dims X Y Z");
    if (!o.isovalue) throw conf::UsageError("--volume needs --isovalue");
    if (o.type != "uint8" && o.type != "uint16") throw conf::UsageError("--type must be uint8 or uint16, not " + o.type);
    conf::IsoScene s = conf::builtInIsoScenes().front();  // its camera and refinement settings
    s.name = o.volume.stem().string();
    s.volumeFile = std::filesystem::absolute(o.volume);
    s.volumeIsUint16 = o.type == "uint16";
    s.data.clear();
    conf::aimOrbitAt(s, {o.dims[0], o.dims[1], o.dims[2]});
    s.isovalue = *o.isovalue;
    scenes.push_back(s);
  } else {
    for (const conf::IsoScene& s : conf::builtInIsoScenes())
      if (o.scene == "all" || o.scene == s.name) scenes.push_back(s);
    if (scenes.empty()) {
      std::string known;
      for (const conf::IsoScene& s : conf::builtInIsoScenes()) known += " " + s.name;
      throw conf::UsageError("no built-in isosurface scene '" + o.scene + "' (known:" + known + ", or all)");
    }
  }
  for (conf::IsoScene& s : scenes) {
    if (o.frames) s.path.frames = *o.frames;
    if (o.isovalue) s.isovalue = *o.isovalue;
  }
  return scenes;
}

}  // namespace

int runFixtures(const FixturesOptions& o) {
  auto progress = [](const std::string& what) { std::cerr << "  " << what << "\n"; };
  if (o.generate) {
    const nlohmann::json manifest = conf::generateIsoFixtures(o.dir, requestedScenes(o), o.threads, progress);
    std::cout << "wrote " << manifest.at("files").size() << " fixture files and " << (o.dir / "manifest.json").string() << "\n";
    return 0;
  }
  const std::vector<conf::FixtureMismatch> problems = conf::verifyIsoFixtures(o.dir, o.threads, progress);
  for (const conf::FixtureMismatch& p : problems) std::cout << "MISMATCH " << p.file << ": " << p.problem << "\n";
  std::cout << (problems.empty() ? "fixtures verified: every file regenerates bit for bit\n" : std::to_string(problems.size()) + " problem(s)\n");
  return problems.empty() ? 0 : 1;
}

}  // namespace voxref::cli
