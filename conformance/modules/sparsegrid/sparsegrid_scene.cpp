#include "conformance/modules/sparsegrid/sparsegrid_scene.h"

#include <memory>

#include "conformance/io/raw_volume.h"

namespace voxref::conf {
namespace {

template <class T, class Parse>
T parseEnum(JsonObjectReader& r, const char* key, T fallback, Parse parse, const char* allowed) {
  if (!r.has(key)) return fallback;
  const std::string s = r.get<std::string>(key);
  const auto v = parse(s);
  if (!v) throw SceneError(r.fieldPath(key) + ": '" + s + "' is not one of " + allowed);
  return *v;
}

glm::dvec3 vec3(JsonObjectReader& r, const char* key) {
  const auto v = r.get<std::vector<double>>(key);
  if (v.size() != 3) throw SceneError(r.fieldPath(key) + ": expected 3 numbers");
  return {v[0], v[1], v[2]};
}

nlohmann::json vec3Json(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

SparseGridScene parseSparseGridScene(const nlohmann::json& j) {
  SparseGridScene s;
  JsonObjectReader r(j, "");
  const std::string system = r.get<std::string>("system", "sparsegrid");
  if (system != "sparsegrid") throw SceneError("system: '" + system + "' is not 'sparsegrid'");
  if (r.has("data")) {
    JsonObjectReader d = r.object("data");
    if (d.has("volume")) {
      s.data.volume = d.get<std::string>("volume");
      const auto dims = d.get<std::vector<int>>("dims");
      if (dims.size() != 3 || dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
        throw SceneError(d.fieldPath("dims") + ": expected 3 extents of at least 2");
      s.data.volumeDims = {dims[0], dims[1], dims[2]};
      const std::string type = d.get<std::string>("type", "uint8");
      if (type != "uint8") throw SceneError(d.fieldPath("type") + ": only uint8 volumes are sparse-grid data");
    } else {
      s.data.field = d.get<std::string>("field", s.data.field);
      try {
        (void)ref::analyticField(s.data.field);
      } catch (const std::invalid_argument& e) {
        throw SceneError(d.fieldPath("field") + ": " + e.what());
      }
    }
    d.finish();
  }
  s.grid.level = r.getInt("level", s.grid.level, ref::kMinSparseLevel, ref::kMaxSparseLevel);
  s.grid.boundary = r.get<bool>("boundary", s.grid.boundary);
  if (r.has("texture")) {
    JsonObjectReader t = r.object("texture");
    s.textures.format = parseEnum(t, "format", s.textures.format, ref::parseTexelFormat, "r8, rgba8, r16, r16f, r32f");
    s.textures.sizing = parseEnum(t, "sizing", s.textures.sizing, ref::parseTextureSizing, "padded, exact");
    s.sampler.filter = parseEnum(t, "filter", s.sampler.filter, ref::parseFilter, "nearest, linear");
    s.sampler.wrap = parseEnum(t, "wrap", s.sampler.wrap, ref::parseWrap, "clamp_to_edge, repeat, clamp_to_border");
    s.sampler.borderRed = t.get<double>("border", s.sampler.borderRed);
    s.textures.maxExtent = t.getInt("max_extent", s.textures.maxExtent, 3, 16384);
    t.finish();
  }
  s.textures.scaling = parseEnum(r, "scaling", s.textures.scaling, ref::parseScalingPolicy, "scaled, unscaled");
  s.framebuffer = parseEnum(r, "framebuffer", s.framebuffer, ref::parseFramebufferFormat,
                            "rgba8, rgba12, rgba16, rgba16f, rgba32f");
  s.flushEachPass = r.get<bool>("flush_each_pass", false);
  s.passOrder = r.get<std::vector<int>>("pass_order", {});
  s.shading.mode = parseEnum(r, "mode", s.shading.mode, ref::parseRenderMode, "xray, mip, iso");
  s.shading.isovalue = r.get<double>("isovalue", s.shading.isovalue);
  s.shading.ambient = r.get<double>("ambient", s.shading.ambient);
  if (r.has("camera")) {
    JsonObjectReader c = r.object("camera");
    if (c.has("origin")) {
      s.camera.origin = vec3(c, "origin");
      s.camera.dx = vec3(c, "dx");
      s.camera.dy = vec3(c, "dy");
      s.camera.dz = vec3(c, "dz");
    } else {
      s.camera.azimuth = c.get<double>("azimuth", s.camera.azimuth);
      s.camera.elevation = c.get<double>("elevation", s.camera.elevation);
    }
    c.finish();
  }
  readFrameExtents(r, s.width, s.height, s.planes);
  r.finish();
  return s;
}

nlohmann::json toJson(const SparseGridScene& s) {
  nlohmann::json j;
  j["system"] = "sparsegrid";
  if (s.data.isVolume())
    j["data"] = {{"volume", s.data.volume.string()}, {"dims", s.data.volumeDims}, {"type", "uint8"}};
  else
    j["data"] = {{"field", s.data.field}};
  j["level"] = s.grid.level;
  j["boundary"] = s.grid.boundary;
  j["texture"] = {{"format", ref::name(s.textures.format)}, {"sizing", ref::name(s.textures.sizing)},
                  {"filter", ref::name(s.sampler.filter)},  {"wrap", ref::name(s.sampler.wrap)},
                  {"border", s.sampler.borderRed},          {"max_extent", s.textures.maxExtent}};
  j["scaling"] = ref::name(s.textures.scaling);
  j["framebuffer"] = ref::name(s.framebuffer);
  j["flush_each_pass"] = s.flushEachPass;
  if (!s.passOrder.empty()) j["pass_order"] = s.passOrder;
  j["mode"] = ref::name(s.shading.mode);
  j["isovalue"] = s.shading.isovalue;
  j["ambient"] = s.shading.ambient;
  if (s.camera.origin)
    j["camera"] = {{"origin", vec3Json(*s.camera.origin)},
                   {"dx", vec3Json(*s.camera.dx)},
                   {"dy", vec3Json(*s.camera.dy)},
                   {"dz", vec3Json(*s.camera.dz)}};
  else
    j["camera"] = {{"azimuth", s.camera.azimuth}, {"elevation", s.camera.elevation}};
  j["image"] = {s.width, s.height};
  j["planes"] = s.planes;
  return j;
}

std::string planeKey(const SparseGridScene& scene) {
  nlohmann::json j = toJson(scene);
  j.erase("mode");
  j.erase("isovalue");
  j.erase("ambient");
  return j.dump();
}

ref::Field loadField(const DataSource& data) {
  if (!data.isVolume()) return ref::analyticField(data.field);
  auto volume = std::make_shared<const ref::Volume<std::uint8_t>>(io::readRawVolumeU8(data.volume, data.volumeDims));
  return ref::volumeField(data.volume.filename().string(), volume, 1.0 / 255.0);
}

ref::PlaneFrame makeFrame(const SparseGridScene& s) {
  try {
    if (s.camera.origin)
      return ref::explicitFrame(*s.camera.origin, *s.camera.dx, *s.camera.dy, *s.camera.dz, s.width, s.height,
                                s.planes);
    return ref::orbitFrame(s.camera.azimuth, s.camera.elevation, s.width, s.height, s.planes);
  } catch (const std::invalid_argument& e) {
    throw SceneError(std::string("camera: ") + e.what());
  }
}

}  // namespace voxref::conf
