#include "emulation/texture_sampler_emu.h"

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "emulation/float32.h"
#include "reference/common/texel_format.h"

namespace voxref::emu {
namespace {

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

// softpipe's repeat(): (c + 1024 size) % size in unsigned arithmetic (sp_tex_sample.c:118-122).
int softpipeRepeat(int c, int size) {
  return static_cast<int>((static_cast<unsigned>(c) + static_cast<unsigned>(size) * 1024u) %
                          static_cast<unsigned>(size));
}

float fractOf(float s) { return s - std::floor(s); }

}  // namespace

TextureSamplerEmu::TextureSamplerEmu(const ref::Dims3& dims, ref::TexelFormat format,
                                     const std::vector<std::uint32_t>& codes, const ref::SamplerState& sampler,
                                     const PrecisionProfile& profile, bool forceAllEffects)
    : dims_(dims), format_(format), codes_(&codes), sampler_(sampler), profile_(&profile), force_(forceAllEffects) {
  const bool unorm8 = ref::unormBits(format) == 8;
  const bool simpleWrap = sampler.wrap == ref::Wrap::Repeat || sampler.wrap == ref::Wrap::ClampToEdge;
  if (sampler.filter == ref::Filter::Nearest)
    path_ = SamplerPath::Nearest;
  else if (profile.aos8BitSampling && unorm8 && simpleWrap)
    path_ = SamplerPath::Aos8Linear;  // lp_bld_sample_soa.c:3739-3766
  else
    path_ = SamplerPath::FloatLinear;
  // Border colour: clamped to [0, 1] for unorm formats, not quantized (sp_tex_sample.c:3731-3741,
  // lp_build_clamp_border_color). GL receives it as a float.
  const float b = static_cast<float>(sampler.borderRed);
  border_ = ref::unormBits(format) ? std::clamp(b, 0.0f, 1.0f) : b;
}

std::vector<Effect> TextureSamplerEmu::effects() const {
  std::vector<Effect> e;
  switch (format_) {
    case ref::TexelFormat::R8:
    case ref::TexelFormat::RGBA8:
      e.push_back(Effect::TexelUnorm8);
      break;
    case ref::TexelFormat::R16:
      e.push_back(Effect::TexelUnorm16);
      break;
    case ref::TexelFormat::R16F:
      e.push_back(Effect::TexelHalf);
      break;
    case ref::TexelFormat::R32F:
      e.push_back(Effect::TexelFloat32);
      break;
  }
  if (ref::unormBits(format_)) e.push_back(Effect::UnormToFloatReciprocal);
  switch (path_) {
    case SamplerPath::Aos8Linear:
      e.push_back(Effect::SamplerAos8Bit);
      break;
    case SamplerPath::FloatLinear:
      e.push_back(Effect::SamplerFloatWeights);
      e.push_back(profile_->floatLerp == LerpArithmetic::Fused ? Effect::LerpFused : Effect::LerpUnfused);
      break;
    case SamplerPath::Nearest:
      e.push_back(Effect::SamplerNearest);
      break;
  }
  if (sampler_.wrap == ref::Wrap::ClampToBorder) e.push_back(Effect::BorderTexels);
  if (path_ == SamplerPath::FloatLinear && profile_->textureTileCache.aliasing) e.push_back(Effect::TileCacheAliasing);
  if (profile_->flushDenormals && path_ == SamplerPath::FloatLinear && format_ == ref::TexelFormat::R32F)
    e.push_back(Effect::FlushDenormals);
  return e;
}

float TextureSamplerEmu::texel(int x, int y, int z) const {
  if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) return border_;
  const std::uint32_t code = (*codes_)[static_cast<std::size_t>(x) + static_cast<std::size_t>(dims_[0]) *
                                                                         (y + static_cast<std::size_t>(dims_[1]) * z)];
  switch (format_) {
    case ref::TexelFormat::R8:
    case ref::TexelFormat::RGBA8:
      return unormToFloat(code, 8);
    case ref::TexelFormat::R16:
      return unormToFloat(code, 16);
    case ref::TexelFormat::R16F:
      return halfToFloat(static_cast<std::uint16_t>(code));
    case ref::TexelFormat::R32F: {
      const float v = std::bit_cast<float>(code);
      return profile_->flushDenormals ? flushDenormal(v) : v;
    }
  }
  return 0.0f;
}

std::uint32_t TextureSamplerEmu::texelCode8(int x, int y, int z) const {
  return (*codes_)[static_cast<std::size_t>(x) +
                   static_cast<std::size_t>(dims_[0]) * (y + static_cast<std::size_t>(dims_[1]) * z)];
}

float TextureSamplerEmu::lerp(float w, float a, float b) const {
  // With FTZ/DAZ every operation's denormal operands and results are zero.
  auto ftz = [this](float x) { return profile_->flushDenormals ? flushDenormal(x) : x; };
  const float d = ftz(b - a);
  if (profile_->floatLerp == LerpArithmetic::Fused) return ftz(std::fma(w, d, a));  // llvm.fmuladd, FMA CPU
  return ftz(a + ftz(w * d));  // sp_tex_sample.c:73-76; lp_build_lerp without FMA
}

// --- Float weights (linear) ----------------------------------------------------------------

TextureSamplerEmu::FloatAxis TextureSamplerEmu::floatLinearAxis(float s, int n) const {
  const float nf = static_cast<float>(n);
  FloatAxis a{};
  if (profile_->sampler == SamplerFamily::Softpipe) {
    // sp_tex_sample.c:279-327.
    float u = 0.0f;
    switch (sampler_.wrap) {
      case ref::Wrap::Repeat:
        u = s * nf - 0.5f;
        a.i0 = softpipeRepeat(softpipeIfloor(u), n);
        a.i1 = softpipeRepeat(a.i0 + 1, n);
        break;
      case ref::Wrap::ClampToEdge: {
        const float c = s * nf;
        u = (c > 0.0f ? (c > nf ? nf : c) : 0.0f) - 0.5f;  // CLAMP: NaN -> min
        a.i0 = softpipeIfloor(u);
        a.i1 = a.i0 + 1;
        if (a.i0 < 0) a.i0 = 0;
        if (a.i1 >= n) a.i1 = n - 1;
        break;
      }
      case ref::Wrap::ClampToBorder: {
        const float c = s * nf, hi = nf + 0.5f;
        u = (c > -1.0f ? (c > hi ? hi : c) : -1.0f) - 0.5f;
        a.i0 = softpipeIfloor(u);
        a.i1 = a.i0 + 1;
        break;
      }
    }
    a.w = u - std::floor(u);
    return a;
  }
  // llvmpipe SoA, lp_bld_sample_soa.c:319-672.
  switch (sampler_.wrap) {
    case ref::Wrap::Repeat:
      if (isPowerOfTwo(n)) {
        const float u = s * nf - 0.5f;
        const float f = std::floor(u);
        a.w = u - f;
        a.i0 = static_cast<int>(f) & (n - 1);
        a.i1 = (static_cast<int>(f) + 1) & (n - 1);
      } else {
        const float u = fractOf(s) * nf - 0.5f;
        const float f = std::floor(u);
        a.w = u - f;
        a.i0 = u < 0.0f ? n - 1 : static_cast<int>(f);
        a.i1 = a.i0 != n - 1 ? a.i0 + 1 : 0;
      }
      break;
    case ref::Wrap::ClampToEdge: {
      float u = s * nf;
      u = std::isnan(u) ? nf : std::min(u, nf);
      u = std::max(u - 0.5f, 0.0f);
      const float f = std::floor(u);
      a.w = u - f;
      a.i0 = static_cast<int>(f);
      a.i1 = std::min(a.i0 + 1, n - 1);
      break;
    }
    case ref::Wrap::ClampToBorder: {
      const float u = s * nf - 0.5f;
      const float f = std::floor(u);
      a.w = u - f;
      a.i0 = static_cast<int>(f);
      a.i1 = a.i0 + 1;
      break;
    }
  }
  return a;
}

// --- 8-bit AoS (linear) ----------------------------------------------------------------------

TextureSamplerEmu::FixedAxis TextureSamplerEmu::aosLinearAxis(float s, int n) const {
  FixedAxis a{};
  if (sampler_.wrap == ref::Wrap::Repeat && !isPowerOfTwo(n)) {
    // lp_build_coord_repeat_npot_linear_int (lp_bld_sample_aos.c:139-205).
    const float scaled = (fractOf(s) * static_cast<float>(n)) * 256.0f;
    const int k = roundHalfEvenToInt(scaled) - 128;
    a.w = k & 255;
    a.i0 = k >> 8;
    if (a.i0 < 0) a.i0 = n - 1;
    a.i0 = std::min(a.i0, n - 1);
    a.i1 = a.i0 != n - 1 ? a.i0 + 1 : 0;
    return a;
  }
  const float scaled = s * static_cast<float>(n << 8);  // lp_build_unnormalized_coords: one multiply
  const int k = roundHalfEvenToInt(scaled) - 128;
  a.i0 = k >> 8;  // arithmetic shift: floor
  a.w = k & 255;
  if (sampler_.wrap == ref::Wrap::Repeat) {
    a.i0 &= n - 1;
    a.i1 = a.i0 != n - 1 ? a.i0 + 1 : 0;
  } else {  // CLAMP_TO_EDGE (lp_build_sample_wrap_linear_int)
    const bool inside = a.i0 >= 0 && a.i0 < n - 1;
    a.i0 = std::clamp(a.i0, 0, n - 1);
    a.i1 = a.i0 + (inside ? 1 : 0);
  }
  return a;
}

// --- Nearest ---------------------------------------------------------------------------------

int nearestTexelIndex(float s, int n, ref::Wrap wrap, const PrecisionProfile& profile) {
  const float nf = static_cast<float>(n);
  if (profile.sampler == SamplerFamily::Softpipe) {
    const float u = s * nf;  // sp_tex_sample.c:133-195
    switch (wrap) {
      case ref::Wrap::Repeat:
        return softpipeRepeat(softpipeIfloor(u), n);
      case ref::Wrap::ClampToEdge:
        if (u < 0.5f) return 0;
        if (u > nf - 0.5f) return n - 1;
        return std::clamp(softpipeIfloor(u), 0, n - 1);  // NaN: util_ifloor gives 0
      case ref::Wrap::ClampToBorder:
        if (u <= -0.5f) return -1;
        if (u >= nf + 0.5f) return n;
        return softpipeIfloor(u);
    }
    return 0;
  }
  // Float to int as cvttps2dq / cvtps2dq do it: NaN and out-of-range values give INT_MIN.
  auto toInt = [](float v) { return std::isnan(v) || std::fabs(v) >= 2147483648.0f ? INT32_MIN : static_cast<int>(v); };
  switch (wrap) {  // lp_bld_sample_soa.c:686-815 (and lp_bld_sample_aos.c:77-136)
    case ref::Wrap::Repeat:
      if ((n & (n - 1)) == 0) return toInt(std::floor(s * nf)) & (n - 1);
      return toInt(std::trunc(std::min(fractOf(s), 0x1.fffffep-1f) * nf));
    case ref::Wrap::ClampToEdge:
      return std::clamp(toInt(std::trunc(s * nf)), 0, n - 1);
    case ref::Wrap::ClampToBorder: {
      const int i = toInt(std::floor(s * nf));
      if (i == INT32_MIN || i < 0) return -1;
      return std::min(i, n);
    }
  }
  return 0;
}

float TextureSamplerEmu::weightStageIdentity(float value, float s, float t, float r) const {
  if (!std::isfinite(value)) return value;  // inf - inf: the stage is an identity only on finite values
  const int n[3] = {std::max(dims_[0], 1), std::max(dims_[1], 1), std::max(dims_[2], 1)};
  const float c[3] = {s, t, r};
  float w[3];
  for (int a = 0; a < 3; ++a) {
    w[a] = floatLinearAxis(c[a], n[a]).w;
    if (!(w[a] >= 0.0f && w[a] <= 1.0f)) w[a] = 0.0f;  // NaN or infinite coordinates
  }
  const float row = lerp(w[0], value, value);  // x on the four edges: all equal
  const float slice = lerp(w[1], row, lerp(w[0], value, value));
  const float slice1 = lerp(w[1], lerp(w[0], value, value), lerp(w[0], value, value));
  const float v = lerp(w[2], slice, slice1);
  // -0 + 0 = +0: keep the texel's own zero (the stage changes no bit of any finite value).
  return v == 0.0f ? value : v;
}

// --- Sampling ----------------------------------------------------------------------------------

void TextureSamplerEmu::aliasTaps(const int x[2], const int y[2], const int z[2], float values[8],
                                  bool* unmodelled) const {
  const TextureTileCache& cache = profile_->textureTileCache;
  if (cache.slots > 64) throw std::logic_error("texture tile caches of more than 64 slots are not modelled");
  const int size = cache.tileSize;
  struct Tile {
    int tx, ty, tz;
    bool operator==(const Tile&) const = default;
  };
  auto inside = [&](int xi, int yi, int zi) {
    return xi >= 0 && yi >= 0 && zi >= 0 && xi < dims_[0] && yi < dims_[1] && zi < dims_[2];
  };
  Tile own[8];
  bool border[8];
  std::array<Tile, 64> occupant{};  // slots (at most 64 supported; softpipe has 16)
  std::array<bool, 64> used{};
  // Fetch order of img_filter_3d_linear: (x0,y0,z0) (x1,y0,z0) (x0,y1,z0) (x1,y1,z0), then z1.
  for (int n = 0; n < 8; ++n) {
    const int xi = x[n & 1], yi = y[(n >> 1) & 1], zi = z[n >> 2];
    border[n] = !inside(xi, yi, zi);  // a pointer to the border colour, not into the cache
    if (border[n]) continue;
    own[n] = {xi / size, yi / size, zi};
    const int slot = (own[n].tx + cache.yMultiplier * own[n].ty + own[n].tz) % cache.slots;
    occupant[slot] = own[n];
    used[slot] = true;
  }
  for (int n = 0; n < 8; ++n) {
    const int xi = x[n & 1], yi = y[(n >> 1) & 1];
    if (border[n]) {
      values[n] = border_;
      continue;
    }
    const Tile& o = occupant[(own[n].tx + cache.yMultiplier * own[n].ty + own[n].tz) % cache.slots];
    const int gx = o.tx * size + xi % size, gy = o.ty * size + yi % size;
    if (o == own[n] || inside(gx, gy, o.tz)) {
      values[n] = texel(gx, gy, o.tz);
    } else {
      values[n] = std::numeric_limits<float>::quiet_NaN();  // stale data of an earlier tile
      if (unmodelled) *unmodelled = true;
    }
  }
}

float TextureSamplerEmu::sampleRed(float s, float t, float r, bool* unmodelled) const {
  switch (path_) {
    case SamplerPath::Nearest: {
      const int x = nearestTexelIndex(s, dims_[0], sampler_.wrap, *profile_),
                y = nearestTexelIndex(t, dims_[1], sampler_.wrap, *profile_),
                z = nearestTexelIndex(r, dims_[2], sampler_.wrap, *profile_);
      return force_ ? weightStageIdentity(texel(x, y, z), s, t, r) : texel(x, y, z);
    }
    case SamplerPath::Aos8Linear: {
      const FixedAxis ax = aosLinearAxis(s, dims_[0]), ay = aosLinearAxis(t, dims_[1]), az = aosLinearAxis(r, dims_[2]);
      // pmulhrsw rounding (SSSE3 / AVX2): a + floor((w (b - a) + 128) / 256); without SSSE3 the
      // product is shifted down without rounding: a + floor(w (b - a) / 256).
      const int half = profile_->aosLerp == Lerp8Rounding::Nearest ? 128 : 0;
      auto lerp8 = [half](int w, int a, int b) { return a + ((w * (b - a) + half) >> 8); };
      auto v = [&](int x, int y, int z) { return static_cast<int>(texelCode8(x, y, z)); };
      auto slice = [&](int z) {
        const int row0 = lerp8(ax.w, v(ax.i0, ay.i0, z), v(ax.i1, ay.i0, z));
        const int row1 = lerp8(ax.w, v(ax.i0, ay.i1, z), v(ax.i1, ay.i1, z));
        return lerp8(ay.w, row0, row1);
      };
      const int result = lerp8(az.w, slice(az.i0), slice(az.i1));
      return unormToFloat(static_cast<std::uint32_t>(result), 8);
    }
    case SamplerPath::FloatLinear: {
      const FloatAxis ax = floatLinearAxis(s, dims_[0]), ay = floatLinearAxis(t, dims_[1]),
                      az = floatLinearAxis(r, dims_[2]);
      if (profile_->textureTileCache.aliasing) {
        const int xs[2] = {ax.i0, ax.i1}, ys[2] = {ay.i0, ay.i1}, zs[2] = {az.i0, az.i1};
        float v[8];
        aliasTaps(xs, ys, zs, v, unmodelled);
        const float s0 = lerp(ay.w, lerp(ax.w, v[0], v[1]), lerp(ax.w, v[2], v[3]));
        const float s1 = lerp(ay.w, lerp(ax.w, v[4], v[5]), lerp(ax.w, v[6], v[7]));
        return lerp(az.w, s0, s1);
      }
      auto slice = [&](int z) {
        const float row0 = lerp(ax.w, texel(ax.i0, ay.i0, z), texel(ax.i1, ay.i0, z));
        const float row1 = lerp(ax.w, texel(ax.i0, ay.i1, z), texel(ax.i1, ay.i1, z));
        return lerp(ay.w, row0, row1);
      };
      return lerp(az.w, slice(az.i0), slice(az.i1));
    }
  }
  return 0.0f;
}

}  // namespace voxref::emu
