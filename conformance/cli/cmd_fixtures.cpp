// voxref fixtures generate | verify: the Embree ground truth of the isosurface system
// (conformance/modules/iso/iso_fixtures.h) for the built-in scenes or the user's own volume.
#include <algorithm>
#include <iostream>
#include <memory>

#include "conformance/cli/commands.h"
#include "conformance/framework/exit_status.h"
#include "conformance/modules/iso/iso_fixtures.h"

namespace voxref::cli {
namespace {

struct FixturesOptions {
  bool generate = false;  // else verify
  std::filesystem::path dir;
  std::string scene = "all";     // a built-in scene name, or all
  std::optional<int> frames;     // none: the scene's own orbit length
  std::filesystem::path volume;  // the user's volume instead of a built-in scene
  std::vector<int> dims;
  std::string type = "uint8";
  std::optional<double> isovalue;  // finite (checked when parsed)
  int threads = 0;
};

namespace {

std::vector<conf::IsoScene> requestedScenes(const FixturesOptions& o) {
  std::vector<conf::IsoScene> scenes;
  if (!o.volume.empty()) {
    if (o.dims.size() != 3) throw conf::UsageError("--volume needs --dims X Y Z");
    if (!o.isovalue) throw conf::UsageError("--volume needs --isovalue");
    if (o.type != "uint8" && o.type != "uint16")
      throw conf::UsageError("--type must be uint8 or uint16, not " + o.type);
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
    std::cout << "wrote " << manifest.at("files").size() << " fixture files and " << (o.dir / "manifest.json").string()
              << "\n";
    return 0;
  }
  const std::vector<conf::FixtureMismatch> problems = conf::verifyIsoFixtures(o.dir, o.threads, progress);
  for (const conf::FixtureMismatch& p : problems) std::cout << "MISMATCH " << p.file << ": " << p.problem << "\n";
  std::cout << (problems.empty() ? "fixtures verified: every file regenerates bit for bit\n"
                                 : std::to_string(problems.size()) + " problem(s)\n");
  return problems.empty() ? 0 : 1;
}

}  // namespace

Subcommand addFixturesCommand(CLI::App& app) {
  auto o = std::make_shared<FixturesOptions>();
  CLI::App* sub =
      app.add_subcommand("fixtures", "Embree ground truth of the isosurface scenes: generate, or verify bit for bit");
  sub->require_subcommand(1);
  for (const bool generate : {true, false}) {
    CLI::App* mode = sub->add_subcommand(generate ? "generate" : "verify",
                                         generate ? "write EXR fixtures and a manifest with sha256 of every file"
                                                  : "regenerate from the manifest and compare every file");
    mode->add_option("--dir", o->dir, "fixture directory (holds manifest.json)")->required();
    mode->add_option("--threads", o->threads, "CPU threads (0: all); results are the same for any count")
        ->default_val(0);
    if (!generate) continue;
    mode->callback([o] { o->generate = true; });
    mode->add_option("--scene", o->scene, "built-in scene (iso.frames.<scene>), or all")->default_val("all");
    mode->add_option("--frames", o->frames, "frames of the orbit (default: the scene's)")
        ->check(CLI::Range(1, conf::kMaxIsoSceneFrames));  // the bound the manifest reader applies
    mode->add_option("--volume", o->volume, "your raw volume (.raw or .raw.gz) instead of a built-in scene");
    mode->add_option("--dims", o->dims, "X Y Z of --volume")->expected(3);
    mode->add_option("--type", o->type, "voxel type of --volume: uint8 or uint16 (little endian)")
        ->default_val("uint8");
    mode->add_option("--isovalue", o->isovalue, "isovalue for --volume (or to override the scene's)")
        ->check(finiteNumber());
  }
  return {sub, [o] { return runFixtures(*o); }};
}

}  // namespace voxref::cli
