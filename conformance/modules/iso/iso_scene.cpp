#include "conformance/modules/iso/iso_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "conformance/io/raw_volume.h"
#include "reference/common/fields.h"

namespace voxref::conf {

nlohmann::json toJson(const IsoScene& s) {
  const auto v3 = [](const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
  return {
      {"name", s.name},
      {"data", s.data},
      {"volume_file", s.volumeFile.string()},
      {"volume_uint16", s.volumeIsUint16},
      {"dims", s.dims},
      {"isovalue", s.isovalue},
      {"orbit",
       {{"center", v3(s.path.center)},
        {"radius", s.path.radius},
        {"elevation_deg", s.path.elevationDegrees},
        {"azimuth_start_deg", s.path.azimuthStartDegrees},
        {"azimuth_end_deg", s.path.azimuthEndDegrees},
        {"frames", s.path.frames}}},
      {"camera",
       {{"width", s.camera.width},
        {"height", s.camera.height},
        {"fov_y_deg", s.camera.fovYDegrees},
        {"near", s.camera.nearPlane},
        {"far", s.camera.farPlane}}},
      {"refinement",
       {{"threshold_px", s.budget.threshold}, {"max_splits", s.budget.maxSplits}, {"max_merges", s.budget.maxMerges}}}};
}

IsoScene isoSceneFromJson(const nlohmann::json& j) {
  constexpr std::int64_t kMaxBudget = std::numeric_limits<std::int64_t>::max();
  IsoScene s;
  JsonObjectReader r(j, "");
  s.name = r.get<std::string>("name");
  s.data = r.get<std::string>("data");
  s.volumeFile = r.get<std::string>("volume_file");
  s.volumeIsUint16 = r.get<bool>("volume_uint16");
  const std::vector<std::int64_t> dims = r.getIntegers("dims", 3, 1, kMaxIsoSceneExtent);
  for (std::size_t a = 0; a < 3; ++a) s.dims[a] = static_cast<int>(dims[a]);
  s.isovalue = r.get<double>("isovalue");
  JsonObjectReader o = r.object("orbit");
  const auto c = o.get<std::vector<double>>("center");
  if (c.size() != 3) throw JsonFieldError("orbit.center: expected 3 numbers");
  s.path.center = {c[0], c[1], c[2]};
  s.path.radius = o.get<double>("radius");
  s.path.elevationDegrees = o.get<double>("elevation_deg");
  s.path.azimuthStartDegrees = o.get<double>("azimuth_start_deg");
  s.path.azimuthEndDegrees = o.get<double>("azimuth_end_deg");
  s.path.frames = static_cast<int>(o.getInteger("frames", 1, kMaxIsoSceneFrames));
  o.finish();
  JsonObjectReader cam = r.object("camera");
  s.camera.width = static_cast<int>(cam.getInteger("width", 1, kMaxIsoSceneImageSide));
  s.camera.height = static_cast<int>(cam.getInteger("height", 1, kMaxIsoSceneImageSide));
  s.camera.fovYDegrees = cam.get<double>("fov_y_deg");
  s.camera.nearPlane = cam.get<double>("near");
  s.camera.farPlane = cam.get<double>("far");
  cam.finish();
  JsonObjectReader budget = r.object("refinement");
  s.budget.threshold = budget.get<double>("threshold_px");
  s.budget.maxSplits = static_cast<std::size_t>(budget.getInteger("max_splits", 0, kMaxBudget));
  s.budget.maxMerges = static_cast<std::size_t>(budget.getInteger("max_merges", 0, kMaxBudget));
  budget.finish();
  r.finish();  // unknown keys are refused, as in the other scene readers
  validateIsoScene(s);
  return s;
}

void validateIsoScene(const IsoScene& s) {
  // What regenerating the scene would refuse is refused here, naming the field: a data name that is
  // no field, and an orbit or camera that is degenerate at some frame (fov, near and far, eye on
  // the target).
  if (!std::isfinite(s.isovalue))
    throw JsonFieldError("isovalue: expected a finite number, got " + std::to_string(s.isovalue));
  for (std::size_t a = 0; a < 3; ++a)
    if (s.dims[a] < 1 || s.dims[a] > kMaxIsoSceneExtent)
      throw JsonFieldError("dims[" + std::to_string(a) + "]: expected 1.." + std::to_string(kMaxIsoSceneExtent) +
                           ", got " + std::to_string(s.dims[a]));
  if (s.volumeFile.empty() && s.data != "single_voxel" && s.data != "plateau" && s.data != "empty" &&
      s.data != "full") {
    try {
      (void)ref::analyticField(s.data);
    } catch (const std::invalid_argument& e) {
      throw JsonFieldError(std::string("data: ") + e.what());
    }
  }
  try {
    for (int f = 0; f < s.path.frames; ++f) (void)ref::cameraBasis(ref::orbitCamera(s.path, f, s.camera));
  } catch (const std::invalid_argument& e) {
    throw JsonFieldError(e.what());  // "camera: fov_y must be in (0, 180) degrees", "camera: need 0 < near < far"
  }
}

ref::Volume<std::uint16_t> isoSceneVolume(const IsoScene& scene) {
  if (!scene.volumeFile.empty()) {
    if (scene.volumeIsUint16) return io::readRawVolumeU16(scene.volumeFile, scene.dims);
    return ref::widenToU16(io::readRawVolumeU8(scene.volumeFile, scene.dims));
  }
  if (scene.data == "single_voxel") {  // one voxel of 200 in zeros, off every symmetry plane
    const int x = scene.dims[0] / 2 + 1, y = scene.dims[1] / 2 - 2, z = scene.dims[2] / 2 + 3;
    if (x >= scene.dims[0] || y < 0 || z >= scene.dims[2])
      throw std::invalid_argument("single_voxel: the voxel (" + std::to_string(x) + ", " + std::to_string(y) + ", " +
                                  std::to_string(z) + ") is outside the " + std::to_string(scene.dims[0]) + "x" +
                                  std::to_string(scene.dims[1]) + "x" + std::to_string(scene.dims[2]) +
                                  " volume (it needs at least 3x4x7)");
    ref::Volume<std::uint16_t> v(scene.dims, 0);
    v.at(x, y, z) = 200;
    return v;
  }
  if (scene.data == "empty") return ref::Volume<std::uint16_t>(scene.dims, 0);     // all zero
  if (scene.data == "full") return ref::Volume<std::uint16_t>(scene.dims, 65535);  // all at the 16-bit maximum
  if (scene.data == "plateau") {  // a box of exactly the isovalue in zeros: a flat region at it
    if (!(scene.isovalue >= 0.0 && scene.isovalue <= 65535.0))
      throw std::invalid_argument("plateau: the isovalue " + std::to_string(scene.isovalue) +
                                  " is not a 16-bit sample value (0..65535)");
    ref::Volume<std::uint16_t> v(scene.dims, 0);
    for (int z = scene.dims[2] / 4; z < 3 * scene.dims[2] / 4; ++z)
      for (int y = scene.dims[1] / 3; y < 2 * scene.dims[1] / 3; ++y)
        for (int x = scene.dims[0] / 4; x < scene.dims[0] / 2; ++x)
          v.at(x, y, z) = static_cast<std::uint16_t>(scene.isovalue);
    return v;
  }
  return ref::widenToU16(ref::sampleFieldU8(ref::analyticField(scene.data), scene.dims));
}

void aimOrbitAt(IsoScene& s, const ref::Dims3& dims) {
  s.dims = dims;
  const double c = std::max((std::max({dims[0], dims[1], dims[2]}) - 1) / 2.0, 0.5);
  s.path.center = {(dims[0] - 1) / 2.0, (dims[1] - 1) / 2.0, (dims[2] - 1) / 2.0};
  s.path.radius = 2.2 * c;
  s.camera.farPlane = 8.0 * c;
}

std::vector<IsoScene> builtInIsoScenes() {
  auto base = [](std::string name, std::string data, ref::Dims3 dims, double iso) {
    IsoScene s;
    s.name = std::move(name);
    s.data = std::move(data);
    aimOrbitAt(s, dims);
    s.isovalue = iso;
    s.path.elevationDegrees = 25.0;
    s.path.azimuthStartDegrees = 10.0;
    s.path.azimuthEndDegrees = 130.0;
    s.path.frames = 8;
    s.camera.width = s.camera.height = 96;
    s.camera.fovYDegrees = 40.0;
    s.camera.nearPlane = 0.5;
    s.budget.threshold = 1.0;
    s.budget.maxSplits = 6000;
    return s;
  };
  std::vector<IsoScene> scenes;
  scenes.push_back(base("buckyball", "gaussian_buckyball", {65, 65, 65}, 85.0));
  scenes.push_back(base("hydrogen", "hydrogen_orbital", {65, 65, 65}, 60.0));
  IsoScene blobs = base("blobs_not_a_cube", "gaussian_blobs", {61, 47, 53}, 100.0);
  blobs.isovalueChangeFrame = 4;
  blobs.isovalueStep = 30.0;
  scenes.push_back(blobs);
  return scenes;
}

std::vector<IsoScene> hardIsoScenes() {
  std::vector<IsoScene> scenes;
  for (IsoScene s : builtInIsoScenes()) {
    if (s.name != "buckyball") continue;
    s.path.frames = 3;
    IsoScene single = s, plateau = s, outside = s, boundary = s;
    single.name = "single_voxel";
    single.data = "single_voxel";
    single.isovalue = 100.0;
    single.budget.threshold = 0.25;
    plateau.name = "flat_region_at_isovalue";
    plateau.data = "plateau";
    plateau.isovalue = 120.0;
    outside.name = "isovalue_outside_range";
    outside.isovalue = 300.0;
    boundary.name = "surface_touching_boundary";
    boundary.data = "gaussian_blobs";
    boundary.dims = {40, 65, 50};  // cut through the blobs: surfaces end on the volume's faces
    boundary.isovalue = 60.0;
    IsoScene empty = s, full = s;  // no surface anywhere: the codec and the frame loop on constant extremes
    empty.name = "empty_volume";
    empty.data = "empty";
    empty.isovalue = 120.0;
    full.name = "full_volume";
    full.data = "full";
    full.isovalue = 120.0;
    scenes.insert(scenes.end(), {single, plateau, outside, boundary, empty, full});
  }
  return scenes;
}

}  // namespace voxref::conf
