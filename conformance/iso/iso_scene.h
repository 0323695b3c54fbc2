// An isosurface scene (Gregorski et al. 2004, sections 4-5): a synthetic volume compressed with
// the LEB codec, an isovalue, a scripted camera orbit and the refinement's threshold and budget.
// Camera paths are data, so every run is reproducible. Built-in scenes need no shared data.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "reference/common/view_camera.h"
#include "reference/common/volume.h"
#include <nlohmann/json.hpp>

#include "reference/iso/view_refinement.h"

namespace voxref::conf {

struct IsoScene {
  std::string name;
  std::filesystem::path volumeFile;  // a raw volume of the user's (.raw or .raw.gz), instead of data
  bool volumeIsUint16 = false;       // little endian
  std::string data = "gaussian_buckyball";  // an analytic field (reference/common/fields.h) sampled as uint8,
                                            // or "single_voxel" / "plateau" / "empty" / "full" (hard cases)
  ref::Dims3 dims{65, 65, 65};
  double isovalue = 85.0;
  ref::OrbitPath path;       // centre, radius, elevation, azimuths, frames
  ref::ViewCamera camera;    // size, field of view, near and far (eye and target from the path)
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
// 8 half-extents; sets scene.dims.
void aimOrbitAt(IsoScene& scene, const ref::Dims3& dims);

// The scene as JSON and back (fixture manifests). fromJson throws nlohmann::json exceptions that
// name the missing or mistyped key.
nlohmann::json toJson(const IsoScene& scene);
IsoScene isoSceneFromJson(const nlohmann::json& j);

// The volume of the scene (deterministic). Throws io::IoError for a missing or short volume file.
ref::Volume<std::uint16_t> isoSceneVolume(const IsoScene& scene);

std::vector<IsoScene> builtInIsoScenes();
// The hard cases (issue 5): a single-voxel feature, a flat region exactly at the isovalue, an
// isovalue outside the data range, surfaces touching the volume's boundary. The isovalue 85 of
// the buckyball scene equals many samples of its uint8 data exactly (the rule of
// reference/iso/marching_tetrahedra.h decides them).
std::vector<IsoScene> hardIsoScenes();

}  // namespace voxref::conf
