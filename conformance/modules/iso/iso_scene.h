// An isosurface scene (Gregorski et al. 2004, sections 4-5): a synthetic volume compressed with
// the LEB codec, an isovalue, a scripted camera orbit and the refinement's threshold and budget.
// Camera paths are data, so every run is reproducible. Built-in scenes need no shared data.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include "conformance/framework/json_reader.h"
#include "reference/common/view_camera.h"
#include "reference/common/volume.h"

#include "reference/iso/view_refinement.h"
#include "reference/leb/leb_grid.h"

namespace voxref::conf {

struct IsoScene {
  std::string name;
  std::filesystem::path volumeFile;         // a raw volume of the user's (.raw or .raw.gz), instead of data
  bool volumeIsUint16 = false;              // little endian
  std::string data = "gaussian_buckyball";  // an analytic field (reference/common/fields.h) sampled as uint8,
                                            // or "single_voxel" / "plateau" / "empty" / "full" (hard cases)
  ref::Dims3 dims{65, 65, 65};
  double isovalue = 85.0;
  ref::OrbitPath path;     // centre, radius, elevation, azimuths, frames
  ref::ViewCamera camera;  // size, field of view, near and far (eye and target from the path)
  ref::RefinementBudget budget;
  bool occlusionCulling = true;
  int retestVisibleEvery = 3;  // frames between occlusion tests of a diamond found visible
  // After drawing a frame, test the culled diamonds' boxes against that frame's own depth and undo
  // the culls that show (refine and extract again): the previous frame's surface is not the
  // current one, so the paper's scheme alone can cull a diamond that has just come into view.
  bool verifyCulls = false;
  bool cullEveryTested = false;  // a deliberately broken culler (negative control of the occlusion oracle)
  int isovalueChangeFrame = -1;  // >= 0: the isovalue moves by isovalueStep at this frame
  double isovalueStep = 0.0;
};

// Points the orbit at the centre of `dims` at 2.2 half-extents of its largest axis, the far plane at
// 8 half-extents (a half-extent of at least 0.5: a single sample still gets a valid camera); sets
// scene.dims.
void aimOrbitAt(IsoScene& scene, const ref::Dims3& dims);

// The scene as JSON and back (fixture manifests). fromJson is strict (json_reader.h, as the other
// scene readers): JsonFieldError naming the field for a missing or unknown key, a value of the wrong type, an integer
// out of range (dims 1..kMaxIsoSceneExtent, the largest grid of the isosurface system; orbit frames
// 1..kMaxIsoSceneFrames; camera width and height 1..kMaxIsoSceneImageSide; refinement budgets
// >= 0), a data name that is no field, or an orbit camera that is degenerate at some frame.
inline constexpr int kMaxIsoSceneExtent = (1 << ref::kMaxIndexedLebK) + 1, kMaxIsoSceneFrames = 10000,
                     kMaxIsoSceneImageSide = 4096;
nlohmann::json toJson(const IsoScene& scene);
IsoScene isoSceneFromJson(const nlohmann::json& j);

// What regenerating a scene would refuse, refused before anything is made: an isovalue that is no
// finite number, a data name that is no field, an orbit camera that is degenerate at some frame.
// Throws JsonFieldError naming the field (isoSceneFromJson calls it; so does the fixture
// generator, for scenes made on the command line).
void validateIsoScene(const IsoScene& scene);

// The volume of the scene (deterministic). Throws io::IoError for a missing or short volume file,
// std::invalid_argument for data it cannot build: an unknown field, a single_voxel volume below
// 3x4x7 (the voxel would be outside), a plateau at an isovalue outside 0..65535.
ref::Volume<std::uint16_t> isoSceneVolume(const IsoScene& scene);

std::vector<IsoScene> builtInIsoScenes();
// The hard cases (issue 5): a single-voxel feature, a flat region exactly at the isovalue, an
// isovalue outside the data range, surfaces touching the volume's boundary. The isovalue 85 of
// the buckyball scene equals many samples of its uint8 data exactly (the rule of
// reference/iso/marching_tetrahedra.h decides them).
std::vector<IsoScene> hardIsoScenes();

}  // namespace voxref::conf
