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
  return {{"name", s.name},
          {"data", s.data},
          {"volume_file", s.volumeFile.string()},
          {"volume_uint16", s.volumeIsUint16},
          {"dims", s.dims},
          {"isovalue", s.isovalue},
          {"orbit", {{"center", v3(s.path.center)}, {"radius", s.path.radius}, {"elevation_deg", s.path.elevationDegrees},
                     {"azimuth_start_deg", s.path.azimuthStartDegrees}, {"azimuth_end_deg", s.path.azimuthEndDegrees}, {"frames", s.path.frames}}},
          {"camera", {{"width", s.camera.width}, {"height", s.camera.height}, {"fov_y_deg", s.camera.fovYDegrees}, {"near", s.camera.nearPlane}, {"far", s.camera.farPlane}}},
          {"refinement", {{"threshold_px", s.budget.threshold}, {"max_splits", s.budget.maxSplits}, {"max_merges", s.budget.maxMerges}}}};
}

namespace {

// An integer of the scene, checked before it is converted: nlohmann's get<int>() of 1e300 is
// undefined behaviour and of 2.5 or 2^40 a silent truncation; the range keeps what a manifest
// asks `fixtures verify` to regenerate within what the pipeline holds.
std::int64_t integerAt(const nlohmann::json& v, const std::string& path, std::int64_t lo, std::int64_t hi) {
  if (!v.is_number_integer()) throw JsonFieldError(path + ": expected an integer, got " + v.dump());
  const bool fits = v.is_number_unsigned() ? v.get<std::uint64_t>() <= static_cast<std::uint64_t>(hi) && (lo <= 0 || v.get<std::uint64_t>() >= static_cast<std::uint64_t>(lo))
                                           : v.get<std::int64_t>() >= lo && v.get<std::int64_t>() <= hi;
  if (!fits) throw JsonFieldError(path + ": " + v.dump() + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
  return v.is_number_unsigned() ? static_cast<std::int64_t>(v.get<std::uint64_t>()) : v.get<std::int64_t>();
}

int intAt(const nlohmann::json& o, const char* key, const std::string& path, int lo, int hi) {
  return static_cast<int>(integerAt(o.at(key), path + key, lo, hi));
}

// A number, string or boolean of the scene: a value of another type is a JsonFieldError naming
// the field (nlohmann's get<>() would throw a type_error that names neither).
double numberAt(const nlohmann::json& o, const char* key, const std::string& path = "") {
  const nlohmann::json& v = o.at(key);
  if (!v.is_number()) throw JsonFieldError(path + key + ": expected a number, got " + v.dump());
  return v.get<double>();
}
std::string textAt(const nlohmann::json& o, const char* key) {
  const nlohmann::json& v = o.at(key);
  if (!v.is_string()) throw JsonFieldError(std::string(key) + ": expected a string, got " + v.dump());
  return v.get<std::string>();
}
bool flagAt(const nlohmann::json& o, const char* key) {
  const nlohmann::json& v = o.at(key);
  if (!v.is_boolean()) throw JsonFieldError(std::string(key) + ": expected true or false, got " + v.dump());
  return v.get<bool>();
}

}  // namespace

IsoScene isoSceneFromJson(const nlohmann::json& j) {
  IsoScene s;
  s.name = textAt(j, "name");
  s.data = textAt(j, "data");
  s.volumeFile = textAt(j, "volume_file");
  s.volumeIsUint16 = flagAt(j, "volume_uint16");
  const auto& dims = j.at("dims");
  if (!dims.is_array() || dims.size() != 3) throw JsonFieldError("dims: expected 3 extents, got " + dims.dump());
  for (std::size_t a = 0; a < 3; ++a)
    s.dims[a] = static_cast<int>(integerAt(dims[a], "dims[" + std::to_string(a) + "]", 1, kMaxIsoSceneExtent));
  s.isovalue = numberAt(j, "isovalue");
  const auto& o = j.at("orbit");
  const auto c = o.at("center").get<std::array<double, 3>>();
  s.path.center = {c[0], c[1], c[2]};
  s.path.radius = numberAt(o, "radius", "orbit.");
  s.path.elevationDegrees = numberAt(o, "elevation_deg", "orbit.");
  s.path.azimuthStartDegrees = numberAt(o, "azimuth_start_deg", "orbit.");
  s.path.azimuthEndDegrees = numberAt(o, "azimuth_end_deg", "orbit.");
  s.path.frames = intAt(o, "frames", "orbit.", 1, kMaxIsoSceneFrames);
  const auto& cam = j.at("camera");
  s.camera.width = intAt(cam, "width", "camera.", 1, kMaxIsoSceneImageSide);
  s.camera.height = intAt(cam, "height", "camera.", 1, kMaxIsoSceneImageSide);
  s.camera.fovYDegrees = numberAt(cam, "fov_y_deg", "camera.");
  s.camera.nearPlane = numberAt(cam, "near", "camera.");
  s.camera.farPlane = numberAt(cam, "far", "camera.");
  const auto& r = j.at("refinement");
  s.budget.threshold = numberAt(r, "threshold_px", "refinement.");
  s.budget.maxSplits = static_cast<std::size_t>(integerAt(r.at("max_splits"), "refinement.max_splits", 0, std::numeric_limits<std::int64_t>::max()));
  s.budget.maxMerges = static_cast<std::size_t>(integerAt(r.at("max_merges"), "refinement.max_merges", 0, std::numeric_limits<std::int64_t>::max()));
  validateIsoScene(s);
  return s;
}

void validateIsoScene(const IsoScene& s) {
  // What regenerating the scene would refuse is refused here, naming the field: a data name that is
  // no field, and an orbit or camera that is degenerate at some frame (fov, near and far, eye on
  // the target).
  if (!std::isfinite(s.isovalue)) throw JsonFieldError("isovalue: expected a finite number, got " + std::to_string(s.isovalue));
  for (std::size_t a = 0; a < 3; ++a)
    if (s.dims[a] < 1 || s.dims[a] > kMaxIsoSceneExtent)
      throw JsonFieldError("dims[" + std::to_string(a) + "]: expected 1.." + std::to_string(kMaxIsoSceneExtent) + ", got " + std::to_string(s.dims[a]));
  if (s.volumeFile.empty() && s.data != "single_voxel" && s.data != "plateau" && s.data != "empty" && s.data != "full") {
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
      throw std::invalid_argument("single_voxel: the voxel (" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
                                  ") is outside the " + std::to_string(scene.dims[0]) + "x" + std::to_string(scene.dims[1]) + "x" +
                                  std::to_string(scene.dims[2]) + " volume (it needs at least 3x4x7)");
    ref::Volume<std::uint16_t> v(scene.dims, 0);
    v.at(x, y, z) = 200;
    return v;
  }
  if (scene.data == "empty") return ref::Volume<std::uint16_t>(scene.dims, 0);      // all zero
  if (scene.data == "full") return ref::Volume<std::uint16_t>(scene.dims, 65535);  // all at the 16-bit maximum
  if (scene.data == "plateau") {  // a box of exactly the isovalue in zeros: a flat region at it
    if (!(scene.isovalue >= 0.0 && scene.isovalue <= 65535.0))
      throw std::invalid_argument("plateau: the isovalue " + std::to_string(scene.isovalue) + " is not a 16-bit sample value (0..65535)");
    ref::Volume<std::uint16_t> v(scene.dims, 0);
    for (int z = scene.dims[2] / 4; z < 3 * scene.dims[2] / 4; ++z)
      for (int y = scene.dims[1] / 3; y < 2 * scene.dims[1] / 3; ++y)
        for (int x = scene.dims[0] / 4; x < scene.dims[0] / 2; ++x) v.at(x, y, z) = static_cast<std::uint16_t>(scene.isovalue);
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
