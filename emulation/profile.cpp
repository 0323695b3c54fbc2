#include "emulation/profile.h"

#include <algorithm>
#include <array>

namespace voxref::emu {
namespace {

constexpr PrecisionProfile llvmpipe(std::string_view name, std::string_view summary, bool aos, LerpArithmetic lerp,
                                    std::string_view environment) {
  PrecisionProfile p;
  p.name = name;
  p.summary = summary;
  p.renderer = "llvmpipe";
  p.sampler = SamplerFamily::Llvmpipe;
  p.aos8BitSampling = aos;
  p.floatLerp = lerp;
  p.flushDenormals = true;  // lp_rast.c sets FTZ/DAZ in the rasterizer threads
  p.framebuffer = FramebufferModel::QuantizePerPass;
  p.unorm16Store = UnormRounding::HalfEven;
  p.environment = environment;
  return p;
}

constexpr PrecisionProfile softpipe() {
  PrecisionProfile p;
  p.name = "softpipe";
  p.summary = "Mesa 22.3 softpipe: float weights, unfused lerps, float32 tile cache (no per-pass quantization)";
  p.renderer = "softpipe";
  p.sampler = SamplerFamily::Softpipe;
  p.aos8BitSampling = false;
  p.floatLerp = LerpArithmetic::Unfused;  // plain C, Debian amd64 baseline: no FMA
  p.flushDenormals = false;
  p.framebuffer = FramebufferModel::FloatTileCache;
  p.unorm16Store = UnormRounding::HalfUp;  // util_iround in the generated pack function
  p.textureTileCache.aliasing = true;
  p.texelFetchOutOfRangeClamps = true;
  p.maxModelledTargetWidth = 320;  // 5 tile columns of 64: no two tiles share a cache slot
  p.maxModelledTargetHeight = 640;
  p.environment = "GALLIUM_DRIVER=softpipe";
  return p;
}

constexpr std::array<PrecisionProfile, 5> kProfiles{
    llvmpipe("llvmpipe", "Mesa 22.3 llvmpipe on a CPU with FMA: 8-bit AoS sampling for unorm8, fused float lerps", true,
             LerpArithmetic::Fused, "GALLIUM_DRIVER=llvmpipe, CPU with FMA"),
    llvmpipe("llvmpipe-nofma", "Mesa 22.3 llvmpipe without FMA: 8-bit AoS sampling for unorm8, unfused float lerps",
             true, LerpArithmetic::Unfused, "CPU without FMA, or GALLIUM_OVERRIDE_CPU_CAPS=sse4.1"),
    llvmpipe("llvmpipe-noaos", "Mesa 22.3 llvmpipe with GALLIVM_PERF=no_aos_sampling: float path for every format",
             false, LerpArithmetic::Fused, "GALLIVM_PERF=no_aos_sampling, CPU with FMA"),
    llvmpipe("llvmpipe-noaos-nofma", "Mesa 22.3 llvmpipe, no AoS sampling, no FMA", false, LerpArithmetic::Unfused,
             "GALLIVM_PERF=no_aos_sampling and no FMA (or GALLIUM_OVERRIDE_CPU_CAPS=sse4.1)"),
    softpipe(),
};

}  // namespace

std::span<const PrecisionProfile> knownProfiles() { return kProfiles; }

const PrecisionProfile* findProfile(std::string_view name) {
  for (const PrecisionProfile& p : kProfiles)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<Departure> departuresFromGlSemantics(const PrecisionProfile& profile) {
  std::vector<Departure> out;
  if (profile.framebuffer == FramebufferModel::FloatTileCache) {
    // GL 4.6 section 17.3.6: blending reads the destination from the framebuffer, whose stored
    // format is fixed point: every pass re-quantizes. softpipe's tile cache keeps float32 until
    // a flush, so the semantics are softpipe with a flush after every pass.
    out.push_back({"softpipe.framebuffer.no_per_pass_requantization",
                   "colour kept in a float32 tile cache between blend passes; quantized to the buffer's format "
                   "only when the tile is flushed (read-back), not after every pass",
                   profile, true, Effect::FloatTileCache});
  }
  if (profile.textureTileCache.aliasing) {
    PrecisionProfile fixed = profile;
    fixed.textureTileCache.aliasing = false;
    out.push_back({"softpipe.texture.tile_cache_aliasing",
                   "3D LINEAR lookups whose eight taps span texture tiles that share a slot of the 16-entry tile "
                   "cache read texels of the wrong tile (texel pointers taken before the cache entry is reused)",
                   fixed, false, Effect::TileCacheAliasing});
  }
  return out;
}

std::vector<Departure> departuresAmong(const PrecisionProfile& profile, std::span<const Effect> simulated) {
  std::vector<Departure> out;
  for (Departure& d : departuresFromGlSemantics(profile))
    if (std::find(simulated.begin(), simulated.end(), d.effect) != simulated.end()) out.push_back(std::move(d));
  return out;
}

const PrecisionProfile* autoProfile(std::string_view renderer, std::string_view gallivmPerf,
                                    std::string_view overrideCpuCaps, bool cpuHasFma) {
  if (renderer.rfind("softpipe", 0) == 0) return findProfile("softpipe");
  if (renderer.rfind("llvmpipe", 0) != 0) return nullptr;
  const bool noAos = gallivmPerf.find("no_aos_sampling") != std::string_view::npos;
  // GALLIUM_OVERRIDE_CPU_CAPS (any value voxref knows of: sse*, nosse) removes AVX and with it FMA.
  const bool fma = cpuHasFma && overrideCpuCaps.empty();
  std::string name = noAos ? "llvmpipe-noaos" : "llvmpipe";
  if (!fma) name += "-nofma";
  return findProfile(name);
}

}  // namespace voxref::emu
