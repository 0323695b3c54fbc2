// Embree ground truth as files (fixtures/, docs/design.md): for every frame of a scene's orbit, the
// mesh the refinement extracts for that camera (no occlusion culling, uncompressed field) ray cast
// by Embree, and the exact isosurface of the volume's trilinear field.
//
//   <dir>/<scene>/frame_NN_mesh.exr   Z (eye depth, +inf on a miss), N.x N.y N.z, Y (shade),
//                                     primitive (UINT, triangle index, 0xffffffff on a miss),
//                                     item (UINT, the diamond: hierarchical index of its split
//                                     vertex, 0xffffffff on a miss): which diamonds are visible;
//   <dir>/<scene>/frame_NN_exact.exr  Z, N.x N.y N.z, Y, cell (UINT, x + X (y + Y z) of the cell);
//   <dir>/manifest.json               generator and version, every scene's parameters, and the
//                                     sha256 of every file.
// Rows are stored top first (EXR order). Generation is deterministic: `verify` regenerates every
// file from the manifest's parameters into a temporary folder and compares bytes (sha256).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/modules/iso/iso_scene.h"

namespace voxref::conf {

inline constexpr const char* kFixtureGenerator = "voxref 0.1.0 iso fixtures 2";

// Writes the fixtures and the manifest; returns the manifest. Every scene is validated first
// (validateIsoScene; std::invalid_argument naming the scene), and everything is made in a staging
// folder beside `dir` that is moved into place only when complete (the manifest last): a failure
// leaves nothing behind. Throws io::IoError naming the file for a volume or folder problem.
nlohmann::json generateIsoFixtures(const std::filesystem::path& dir, const std::vector<IsoScene>& scenes, int threads,
                                   const std::function<void(const std::string&)>& progress = {});

struct FixtureMismatch {
  std::string file, problem;
};
// Regenerates and compares. Throws io::FormatError for a manifest that cannot be read.
std::vector<FixtureMismatch> verifyIsoFixtures(const std::filesystem::path& dir, int threads,
                                               const std::function<void(const std::string&)>& progress = {});

}  // namespace voxref::conf
