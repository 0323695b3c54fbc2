#include "conformance/iso/iso_scene.h"

#include <algorithm>

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

IsoScene isoSceneFromJson(const nlohmann::json& j) {
  IsoScene s;
  s.name = j.at("name").get<std::string>();
  s.data = j.at("data").get<std::string>();
  s.volumeFile = j.at("volume_file").get<std::string>();
  s.volumeIsUint16 = j.at("volume_uint16").get<bool>();
  s.dims = j.at("dims").get<ref::Dims3>();
  s.isovalue = j.at("isovalue").get<double>();
  const auto& o = j.at("orbit");
  const auto c = o.at("center").get<std::array<double, 3>>();
  s.path.center = {c[0], c[1], c[2]};
  s.path.radius = o.at("radius").get<double>();
  s.path.elevationDegrees = o.at("elevation_deg").get<double>();
  s.path.azimuthStartDegrees = o.at("azimuth_start_deg").get<double>();
  s.path.azimuthEndDegrees = o.at("azimuth_end_deg").get<double>();
  s.path.frames = o.at("frames").get<int>();
  const auto& cam = j.at("camera");
  s.camera.width = cam.at("width").get<int>();
  s.camera.height = cam.at("height").get<int>();
  s.camera.fovYDegrees = cam.at("fov_y_deg").get<double>();
  s.camera.nearPlane = cam.at("near").get<double>();
  s.camera.farPlane = cam.at("far").get<double>();
  const auto& r = j.at("refinement");
  s.budget.threshold = r.at("threshold_px").get<double>();
  s.budget.maxSplits = r.at("max_splits").get<std::size_t>();
  s.budget.maxMerges = r.at("max_merges").get<std::size_t>();
  return s;
}

ref::Volume<std::uint16_t> isoSceneVolume(const IsoScene& scene) {
  if (!scene.volumeFile.empty()) {
    if (scene.volumeIsUint16) return io::readRawVolumeU16(scene.volumeFile, scene.dims);
    return ref::widenToU16(io::readRawVolumeU8(scene.volumeFile, scene.dims));
  }
  if (scene.data == "single_voxel") {  // one voxel of 200 in zeros, off every symmetry plane
    ref::Volume<std::uint16_t> v(scene.dims, 0);
    v.at(scene.dims[0] / 2 + 1, scene.dims[1] / 2 - 2, scene.dims[2] / 2 + 3) = 200;
    return v;
  }
  if (scene.data == "empty") return ref::Volume<std::uint16_t>(scene.dims, 0);      // all zero
  if (scene.data == "full") return ref::Volume<std::uint16_t>(scene.dims, 65535);  // all at the 16-bit maximum
  if (scene.data == "plateau") {  // a box of exactly the isovalue in zeros: a flat region at it
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
  const double c = (std::max({dims[0], dims[1], dims[2]}) - 1) / 2.0;
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
