#include "conformance/framework/probe/probed_profile.h"

#include <deque>
#include <mutex>
#include <stdexcept>

#include "emulation/probe_emu.h"

namespace voxref::conf {
namespace {

// Strings of profiles made at run time: kept for the life of the process (profiles hold views).
std::string_view keep(std::string s) {
  static std::mutex m;
  static std::deque<std::string> kept;
  const std::lock_guard<std::mutex> lock(m);
  kept.push_back(std::move(s));
  return kept.back();
}

std::string valueOf(const DriverFingerprint& f, const char* id) {
  const InferredProperty* p = f.find(id);
  return p ? p->value : "unknown";
}

}  // namespace

const emu::PrecisionProfile& keepProfile(const emu::PrecisionProfile& p) {
  static std::mutex m;
  static std::deque<emu::PrecisionProfile> kept;
  const std::lock_guard<std::mutex> lock(m);
  kept.push_back(p);
  return kept.back();
}

ProbedProfile profileFromFingerprint(const DriverFingerprint& f, const std::string& name, const std::string& renderer) {
  ProbedProfile out;
  for (const InferredProperty& p : f.properties)
    if (p.value == "unknown") {
      out.problem = p.id + " is unknown (" + p.evidence + ")";
      return out;
    }
  auto unsupported = [&](const char* id) {
    out.problem = std::string(id) + " = " + valueOf(f, id) + ": the emulator has no stage for it";
    return out;
  };
  emu::PrecisionProfile p;
  p.name = keep(name);
  p.renderer = keep(renderer);
  p.probed = true;
  // sampling.unorm8.*: llvmpipe's 8-bit fixed-point path, or float weights like every other format.
  const std::string bits = valueOf(f, "sampling.unorm8.subtexel_bits");
  if (bits == "8") {
    if (valueOf(f, "sampling.unorm8.coordinate_rounding") != "half_even")
      return unsupported("sampling.unorm8.coordinate_rounding");
    const std::string lerp = valueOf(f, "sampling.unorm8.lerp_rounding");
    if (lerp != "nearest" && lerp != "floor") return unsupported("sampling.unorm8.lerp_rounding");
    p.aos8BitSampling = true;
    p.aosLerp = lerp == "nearest" ? emu::Lerp8Rounding::Nearest : emu::Lerp8Rounding::Floor;
  } else if (bits != "float") {
    return unsupported("sampling.unorm8.subtexel_bits");
  }
  if (valueOf(f, "sampling.float.subtexel_bits") != "float") return unsupported("sampling.float.subtexel_bits");
  p.floatLerp =
      valueOf(f, "sampling.float.lerp") == "fused" ? emu::LerpArithmetic::Fused : emu::LerpArithmetic::Unfused;
  // The coordinate formulas: the REPEAT scaling tells gallivm's (fract first) from softpipe's.
  const std::string repeat = valueOf(f, "sampling.float.repeat_scaling");
  p.sampler = repeat == "fract_then_scale" ? emu::SamplerFamily::Llvmpipe : emu::SamplerFamily::Softpipe;
  p.flushDenormals = valueOf(f, "sampling.float.denormals") == "flushed";
  if (valueOf(f, "store.unorm8_rounding") != "half_even") return unsupported("store.unorm8_rounding");
  const std::string store16 = valueOf(f, "store.unorm16_rounding");
  if (store16 != "half_even" && store16 != "half_up") return unsupported("store.unorm16_rounding");
  p.unorm16Store = store16 == "half_even" ? emu::UnormRounding::HalfEven : emu::UnormRounding::HalfUp;
  // Between passes and the RGBA8 blend go together in the emulator's two framebuffer models.
  const std::string between = valueOf(f, "framebuffer.between_passes"), blend = valueOf(f, "blend.rgba8_src_alpha");
  if (between == "requantized" && blend == "mulnorm") {
    p.framebuffer = emu::FramebufferModel::QuantizePerPass;
  } else if (between == "float_tile_cache" && blend == "float") {
    p.framebuffer = emu::FramebufferModel::FloatTileCache;
    // The model of a float tile cache holds while no tile is evicted: assume softpipe's cache.
    p.maxModelledTargetWidth = 320;
    p.maxModelledTargetHeight = 640;
    out.assumed.push_back("a float tile cache that holds targets up to 320 x 640 pixels without evicting a tile");
  } else {
    return unsupported(between != "requantized" && between != "float_tile_cache" ? "framebuffer.between_passes"
                                                                                 : "blend.rgba8_src_alpha");
  }
  out.assumed.push_back("no texture tile-cache aliasing (every tap reads its own texel)");
  out.assumed.push_back("texelFetch outside the texture returns 0");
  out.assumed.push_back("a product with the constant 0.0 is folded to 0 by the compiler");
  std::string summary = "probed from " + renderer + ": ";
  for (std::size_t i = 0; i < f.properties.size(); ++i)
    summary += (i ? ", " : "") + f.properties[i].id + " " + f.properties[i].value;
  p.summary = keep(summary);
  p.environment = keep("the driver as probed");
  out.profile = p;
  return out;
}

std::size_t framesNotReproduced(const ref::ProbeDesign& design, std::span<const ref::ProbeFrame> frames,
                                const emu::PrecisionProfile& profile) {
  const std::vector<ref::ProbeFrame> emulated = emu::emulateProbeFrames(design, profile);
  std::size_t differing = emulated.size() > frames.size() ? emulated.size() - frames.size() : 0;
  for (std::size_t i = 0; i < frames.size(); ++i) differing += i >= emulated.size() || !(emulated[i] == frames[i]);
  return differing;
}

ProbedProfile confirmedProbedProfile(const ref::ProbeDesign& design, std::span<const ref::ProbeFrame> frames,
                                     const DriverFingerprint& fingerprint, const std::string& name,
                                     const std::string& renderer) {
  ProbedProfile out = profileFromFingerprint(fingerprint, name, renderer);
  if (!out.profile) return out;
  const std::size_t differing = framesNotReproduced(design, frames, *out.profile);
  if (differing == 0) return out;
  out.problem = "its emulation differs from the driver in " + std::to_string(differing) + " of " +
                std::to_string(frames.size()) + " probe frames";
  out.profile.reset();
  return out;
}

std::vector<std::string> movedProperties(const nlohmann::json& saved, const DriverFingerprint& now) {
  std::vector<std::string> moved;
  if (!saved.is_array()) return {"properties: not in the saved file"};
  for (const auto& s : saved) {
    const std::string id = s.value("id", ""), value = s.value("value", "");
    const InferredProperty* p = now.find(id);
    if (!p)
      moved.push_back(id + ": probed " + value + ", not measured now");
    else if (p->value != value)
      moved.push_back(id + ": probed " + value + ", now " + p->value);
  }
  return moved;
}

nlohmann::json profileToJson(const emu::PrecisionProfile& p) {
  return {{"name", p.name},
          {"summary", p.summary},
          {"renderer", p.renderer},
          {"environment", p.environment},
          {"probed", p.probed},
          {"sampler", p.sampler == emu::SamplerFamily::Llvmpipe ? "llvmpipe" : "softpipe"},
          {"aos_8bit_sampling", p.aos8BitSampling},
          {"aos_lerp", p.aosLerp == emu::Lerp8Rounding::Nearest ? "nearest" : "floor"},
          {"float_lerp", p.floatLerp == emu::LerpArithmetic::Fused ? "fused" : "unfused"},
          {"flush_denormals", p.flushDenormals},
          {"texture_tile_cache",
           {{"aliasing", p.textureTileCache.aliasing},
            {"tile_size", p.textureTileCache.tileSize},
            {"slots", p.textureTileCache.slots},
            {"y_multiplier", p.textureTileCache.yMultiplier}}},
          {"folds_multiply_by_constant_zero", p.foldsMultiplyByConstantZero},
          {"texel_fetch_out_of_range_clamps", p.texelFetchOutOfRangeClamps},
          {"framebuffer",
           p.framebuffer == emu::FramebufferModel::QuantizePerPass ? "quantize_per_pass" : "float_tile_cache"},
          {"unorm16_store", p.unorm16Store == emu::UnormRounding::HalfEven ? "half_even" : "half_up"},
          {"max_modelled_target", {p.maxModelledTargetWidth, p.maxModelledTargetHeight}}};
}

const emu::PrecisionProfile& profileFromJson(const nlohmann::json& j) {
  auto field = [&](const char* key) -> const nlohmann::json& {
    if (!j.is_object() || !j.contains(key)) throw std::invalid_argument(std::string("profile.") + key + ": missing");
    return j.at(key);
  };
  auto text = [&](const char* key) {
    const auto& v = field(key);
    if (!v.is_string()) throw std::invalid_argument(std::string("profile.") + key + ": expected a string");
    return v.get<std::string>();
  };
  auto flag = [&](const nlohmann::json& v, const std::string& key) {
    if (!v.is_boolean()) throw std::invalid_argument("profile." + key + ": expected true or false");
    return v.get<bool>();
  };
  auto integer = [&](const nlohmann::json& v, const std::string& key) {
    if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > (1ll << 30))
      throw std::invalid_argument("profile." + key + ": expected an integer in 1..2^30");
    return static_cast<int>(v.get<long long>());
  };
  auto choice = [&](const char* key, const char* a, const char* b) {
    const std::string v = text(key);
    if (v != a && v != b)
      throw std::invalid_argument(std::string("profile.") + key + ": expected " + a + " or " + b + ", got " + v);
    return v == a;
  };
  // A named profile: its own fields.
  if (j.is_object() && j.size() == 1 && j.contains("name")) {
    const emu::PrecisionProfile* known = emu::findProfile(text("name"));
    if (!known) throw std::invalid_argument("profile.name: no known profile '" + text("name") + "'");
    return *known;
  }
  emu::PrecisionProfile p;
  p.name = keep(text("name"));
  p.summary = keep(text("summary"));
  p.renderer = keep(text("renderer"));
  p.environment = keep(text("environment"));
  p.probed = flag(field("probed"), "probed");
  p.sampler = choice("sampler", "llvmpipe", "softpipe") ? emu::SamplerFamily::Llvmpipe : emu::SamplerFamily::Softpipe;
  p.aos8BitSampling = flag(field("aos_8bit_sampling"), "aos_8bit_sampling");
  p.aosLerp = choice("aos_lerp", "nearest", "floor") ? emu::Lerp8Rounding::Nearest : emu::Lerp8Rounding::Floor;
  p.floatLerp = choice("float_lerp", "fused", "unfused") ? emu::LerpArithmetic::Fused : emu::LerpArithmetic::Unfused;
  p.flushDenormals = flag(field("flush_denormals"), "flush_denormals");
  const nlohmann::json& cache = field("texture_tile_cache");
  if (!cache.is_object()) throw std::invalid_argument("profile.texture_tile_cache: expected an object");
  p.textureTileCache.aliasing = flag(cache.value("aliasing", nlohmann::json()), "texture_tile_cache.aliasing");
  p.textureTileCache.tileSize = integer(cache.value("tile_size", nlohmann::json()), "texture_tile_cache.tile_size");
  p.textureTileCache.slots = integer(cache.value("slots", nlohmann::json()), "texture_tile_cache.slots");
  p.textureTileCache.yMultiplier =
      integer(cache.value("y_multiplier", nlohmann::json()), "texture_tile_cache.y_multiplier");
  p.foldsMultiplyByConstantZero = flag(field("folds_multiply_by_constant_zero"), "folds_multiply_by_constant_zero");
  p.texelFetchOutOfRangeClamps = flag(field("texel_fetch_out_of_range_clamps"), "texel_fetch_out_of_range_clamps");
  p.framebuffer = choice("framebuffer", "quantize_per_pass", "float_tile_cache")
                      ? emu::FramebufferModel::QuantizePerPass
                      : emu::FramebufferModel::FloatTileCache;
  p.unorm16Store =
      choice("unorm16_store", "half_even", "half_up") ? emu::UnormRounding::HalfEven : emu::UnormRounding::HalfUp;
  const nlohmann::json& target = field("max_modelled_target");
  if (!target.is_array() || target.size() != 2)
    throw std::invalid_argument("profile.max_modelled_target: expected [width, height]");
  p.maxModelledTargetWidth = integer(target[0], "max_modelled_target[0]");
  p.maxModelledTargetHeight = integer(target[1], "max_modelled_target[1]");
  return keepProfile(p);
}

}  // namespace voxref::conf
