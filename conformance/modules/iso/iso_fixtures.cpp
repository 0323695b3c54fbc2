#include "conformance/modules/iso/iso_fixtures.h"

#include <unistd.h>

#include <set>
#include <stdexcept>

#include "conformance/io/atomic_file.h"
#include "conformance/io/image_io.h"
#include "conformance/io/sha256.h"
#include "conformance/modules/iso/iso_manifest.h"
#include "fixtures/raycast/mesh_raycast.h"
#include "fixtures/raycast/trilinear_isosurface.h"
#include "reference/iso/diamond_bounds.h"
#include "reference/iso/extraction.h"
#include "reference/iso/grid_field.h"
#include "reference/leb/gradients.h"

namespace voxref::conf {
namespace {

// Row 0 at the top, as EXR stores it.
template <class T, class Fn>
std::vector<T> topFirst(const fx::RayImage& img, Fn value) {
  std::vector<T> out(static_cast<std::size_t>(img.width) * img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      out[static_cast<std::size_t>(x) + static_cast<std::size_t>(img.width) * (img.height - 1 - y)] =
          value(static_cast<std::size_t>(x) + static_cast<std::size_t>(img.width) * static_cast<std::size_t>(y));
  return out;
}

void writeRayImage(const std::filesystem::path& path, const fx::RayImage& img, const std::string& idName,
                   bool withItems, const std::map<std::string, std::string>& attributes) {
  std::vector<io::ExrChannel> channels;
  channels.push_back({"Z", topFirst<float>(img, [&](std::size_t i) { return img.depth[i]; }), {}});
  channels.push_back({"N.x", topFirst<float>(img, [&](std::size_t i) { return img.normal[i].x; }), {}});
  channels.push_back({"N.y", topFirst<float>(img, [&](std::size_t i) { return img.normal[i].y; }), {}});
  channels.push_back({"N.z", topFirst<float>(img, [&](std::size_t i) { return img.normal[i].z; }), {}});
  channels.push_back({"Y", topFirst<float>(img, [&](std::size_t i) { return img.shade[i]; }), {}});
  channels.push_back({idName, {}, topFirst<std::uint32_t>(img, [&](std::size_t i) { return img.primitive[i]; })});
  if (withItems)
    channels.push_back({"item", {}, topFirst<std::uint32_t>(img, [&](std::size_t i) { return img.item[i]; })});
  io::writeExr(path, img.width, img.height, channels, attributes);
}

std::string frameName(int f) { return std::string(f < 10 ? "frame_0" : "frame_") + std::to_string(f); }

// Writes one scene's files; returns their paths relative to dir.
std::vector<std::string> writeScene(const std::filesystem::path& dir, const IsoScene& scene, int threads,
                                    const std::function<void(const std::string&)>& progress) {
  const ref::Volume<std::uint16_t> volume = isoSceneVolume(scene);
  ref::DenseGridField field(volume, ref::quantizedGradients(volume));
  const ref::DiamondBounds bounds = ref::computeDiamondBounds(field.grid(), field.values(), threads);
  ref::ViewRefinement refinement(bounds, scene.isovalue);
  io::ensureDirectory(dir / scene.name);
  std::vector<std::string> files;
  const std::map<std::string, std::string> attributes{{"generator", kFixtureGenerator}, {"scene", scene.name}};
  for (int f = 0; f < scene.path.frames; ++f) {
    const ref::ViewCamera camera = ref::orbitCamera(scene.path, f, scene.camera);
    refinement.update(camera, scene.budget);
    const ref::IsoMesh mesh = ref::extractIsosurface(refinement.mesh(), field, &bounds, scene.isovalue);
    const std::string base = scene.name + "/" + frameName(f);
    writeRayImage(dir / (base + "_mesh.exr"), fx::castMesh(mesh, camera, threads), "primitive", true, attributes);
    writeRayImage(dir / (base + "_exact.exr"), fx::castTrilinearIsosurface(volume, scene.isovalue, camera, threads),
                  "cell", false, attributes);
    files.push_back(base + "_mesh.exr");
    files.push_back(base + "_exact.exr");
    if (progress) progress(base);
  }
  return files;
}

}  // namespace

nlohmann::json generateIsoFixtures(const std::filesystem::path& dirIn, const std::vector<IsoScene>& scenes, int threads,
                                   const std::function<void(const std::string&)>& progress) {
  // Every scene is checked before anything is made, naming the scene and its data.
  for (const IsoScene& s : scenes) {
    try {
      validateIsoScene(s);
    } catch (const std::exception& e) {
      throw std::invalid_argument("scene '" + s.name + "' (" + (s.volumeFile.empty() ? s.data : s.volumeFile.string()) +
                                  ", " + std::to_string(s.dims[0]) + "x" + std::to_string(s.dims[1]) + "x" +
                                  std::to_string(s.dims[2]) + "): " + e.what());
    }
  }
  const std::filesystem::path dir = dirIn.filename().empty() ? dirIn.parent_path() : dirIn;  // "fx/" is "fx"
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw io::IoError("cannot create directory " + dir.string() + ": a file that is not a directory has that name");
  // Everything is made in a staging folder beside dir (the same file system, so renames), which
  // goes whatever happens: a failure part way (a volume that is missing or of the wrong size, a
  // full disk) leaves nothing behind, not even dir.
  const std::filesystem::path staging =
      dir.parent_path() / (dir.filename().string() + ".tmp" + std::to_string(::getpid()));
  const io::TemporaryFolder stagingFolder(staging);
  nlohmann::json manifest{
      {"generator", kFixtureGenerator}, {"scenes", nlohmann::json::array()}, {"files", nlohmann::json::array()}};
  try {
    for (const IsoScene& s : scenes) {
      manifest["scenes"].push_back(toJson(s));
      for (const std::string& f : writeScene(staging, s, threads, progress))
        manifest["files"].push_back({{"path", f}, {"sha256", io::sha256OfFile(staging / f)}});
    }
    io::writeFileAtomically(staging / "manifest.json", manifest.dump(2) + "\n");
  } catch (const io::IoError& e) {  // named by the destination the user gave, not the staging folder
    std::string what = e.what();
    for (std::size_t at = what.find(staging.string()); at != std::string::npos;
         at = what.find(staging.string(), at + dir.string().size()))
      what.replace(at, staging.string().size(), dir.string());
    throw io::IoError(what + " (while staging in " + staging.string() + ", removed)");
  }
  // Into place: the fixture files first, the manifest that lists them last.
  io::ensureDirectory(dir);
  std::vector<std::string> moves;
  for (const auto& f : manifest["files"]) moves.push_back(f["path"].get<std::string>());
  moves.push_back("manifest.json");
  for (const std::string& f : moves) {
    io::ensureDirectory((dir / f).parent_path());
    std::filesystem::rename(staging / f, dir / f, ec);
    if (ec)
      throw io::IoError("cannot move " + (staging / f).string() + " to " + (dir / f).string() + ": " + ec.message());
  }
  return manifest;
}

std::vector<FixtureMismatch> verifyIsoFixtures(const std::filesystem::path& dir, int threads,
                                               const std::function<void(const std::string&)>& progress) {
  const std::filesystem::path manifestPath = dir / "manifest.json";
  const IsoFixtureManifest manifest = parseIsoFixtureManifest(io::readWholeFile(manifestPath), manifestPath.string());
  std::vector<FixtureMismatch> problems;
  if (manifest.generator != kFixtureGenerator)
    problems.push_back({"manifest.json", "generated by '" +
                                             (manifest.generator.empty() ? std::string("?") : manifest.generator) +
                                             "', this is '" + kFixtureGenerator + "'"});
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("voxref-fixtures-verify-" + std::to_string(::getpid()));
  // The scratch folder goes whatever happens (it was left behind when regeneration threw).
  const io::TemporaryFolder scratchFolder(scratch);
  nlohmann::json again;
  try {
    again = generateIsoFixtures(scratch, manifest.scenes, threads, progress);
  } catch (const std::invalid_argument& e) {  // parameters the pipeline refuses: the manifest is bad
    throw io::FormatError(manifestPath.string() + ": its scenes cannot be regenerated: " + e.what());
  } catch (const io::IoError& e) {  // a volume file it names is missing or wrong, or the scratch folder failed
    throw io::IoError(manifestPath.string() + ": its scenes cannot be regenerated: " + e.what());
  }
  std::set<std::string> regenerated;
  for (const auto& f : again.at("files")) regenerated.insert(f.at("path").get<std::string>());
  for (const IsoFixtureFile& f : manifest.files) {
    const std::string& path = f.path;
    const std::string& listed = f.sha256;
    if (regenerated.erase(path) == 0) {
      problems.push_back({path, "listed in the manifest, not produced by its parameters"});
      continue;
    }
    const std::string fresh = io::sha256OfFile(scratch / path);
    if (fresh != listed)
      problems.push_back({path, "regenerated sha256 " + fresh + " differs from the manifest's " + listed});
    std::error_code ec;
    if (!std::filesystem::is_regular_file(dir / path, ec)) {
      problems.push_back({path, "missing"});
    } else if (const std::string stored = io::sha256OfFile(dir / path); stored != listed) {
      problems.push_back({path, "the file's sha256 " + stored + " differs from the manifest's " + listed});
    }
  }
  for (const std::string& extra : regenerated)
    problems.push_back({extra, "produced by the parameters but not in the manifest"});
  return problems;
}

}  // namespace voxref::conf
