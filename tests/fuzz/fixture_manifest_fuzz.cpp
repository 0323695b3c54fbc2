// libFuzzer target: the manifest.json of the isosurface fixtures (conformance/modules/iso/iso_manifest.h),
// the file `voxref fixtures verify DIR` reads before it regenerates every fixture from the
// manifest's scene parameters. The regeneration itself (Embree ray casting, EXR files) is not
// fuzzed: it is not a parser, and it is what the parser's checks protect; the cheap parts of it
// that take the parsed numbers as they are (the scene's volume, the orbit's cameras) are run.
//
// Contract under test:
// - parseIsoFixtureManifest either returns or throws io::FormatError naming the file; nothing
//   else escapes, nothing reads out of bounds (ASan), no undefined behaviour (UBSan);
// - what it accepts is safe to regenerate: every scene's name is a single plain path component
//   (the scene's files are written under it), every file path is relative and inside the
//   directory, and for scenes of built-in data isoSceneVolume builds the volume in bounds or
//   throws std::invalid_argument; the orbit's cameras are built (ref::orbitCamera) and checked
//   (ref::cameraBasis throws std::invalid_argument for a degenerate one).
// Size cap: isoSceneVolume runs only for volumes of at most 24^3 voxels and the first 4 frames'
// cameras (sampling an analytic field is the slow part); scenes naming a volume file are not
// loaded (the target must not read the machine's files). Parsing is never skipped.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>

#include "conformance/io/atomic_file.h"
#include "conformance/modules/iso/iso_manifest.h"

namespace {

[[noreturn]] void violated(const std::string& what) {
  std::fprintf(stderr, "contract violated: %s\n", what.c_str());
  std::abort();
}

// A path that stays inside the directory it is joined to.
bool insideDirectory(const std::filesystem::path& p) {
  if (p.empty() || p.is_absolute() || p.has_root_path()) return false;
  for (const auto& part : p)
    if (part == ".." || part == ".") return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voxref;
  conf::IsoFixtureManifest m;
  try {
    m = conf::parseIsoFixtureManifest(std::string_view(reinterpret_cast<const char*>(data), size), "manifest.json");
  } catch (const io::FormatError&) {
    return 0;
  }
  for (const conf::IsoFixtureFile& f : m.files)
    if (!insideDirectory(f.path)) violated("file path '" + f.path + "' leaves the fixture directory");
  for (const conf::IsoScene& s : m.scenes) {
    const std::filesystem::path name(s.name);
    if (!insideDirectory(name) || std::distance(name.begin(), name.end()) != 1)
      violated("scene name '" + s.name + "' is not one path component");
    for (int f = 0; f < std::min(s.path.frames, 4); ++f) {
      try {
        (void)ref::cameraBasis(ref::orbitCamera(s.path, f, s.camera));
      } catch (const std::invalid_argument&) {
      }
    }
    if (!s.volumeFile.empty()) continue;
    std::size_t voxels = 0;
    try {
      voxels = ref::sampleCount(s.dims);
    } catch (const std::invalid_argument&) {
      continue;
    }
    if (voxels > 24 * 24 * 24) continue;
    try {
      (void)conf::isoSceneVolume(s);
    } catch (const std::invalid_argument&) {
    }
  }
  return 0;
}
