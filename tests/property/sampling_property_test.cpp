// Property: TextureSamplerEmu::sampleRed (texture_sampler_emu.h, "bit-exact ... for the profiles of
// profile.h") equals, bit for bit, an independent model written from that header and docs/precision.md.
// The model evaluates every float32 step in long double and rounds it to float explicitly (a product
// of two floats is exact in long double; a sum, difference or quotient rounded to long double and
// then to float is correctly rounded because 64 >= 2 * 24 + 2), integer steps with exact floor
// division, and the fused lerp as the correctly rounded w * d + a (exact product, TwoSum error term
// as a sticky bit): it uses neither std::fma nor the emulator's helpers.
//
// Covered: every known llvmpipe profile, unorm8 (AoS 8-bit path or float path, as the profile
// picks), unorm16, binary16 and binary32 texels, LINEAR with CLAMP_TO_EDGE on any size, REPEAT on
// power-of-two sizes, CLAMP_TO_BORDER, and NEAREST with CLAMP_TO_EDGE. Not covered: softpipe (its
// tile-cache aliasing and util_ifloor have their own unit tests) and REPEAT on non-power-of-two
// sizes (a different formula, lp_build_coord_repeat_npot_*). Denormal texels are not generated
// (llvmpipe flushes them; the hard-case catalogue holds those).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emulation/profile.h"
#include "emulation/texture_sampler_emu.h"
#include "reference/common/gl_state.h"
#include "reference/common/texel_format.h"
#include "tests/property/property_seed.h"

namespace voxref::emu {
namespace sampling_property_test {  // named: a unity build compiles several test files together

using property::coin;
using property::Rng;
using property::uniformInt;
using property::uniformUnit;
using L = long double;

// Seeds that once failed (none yet); each stays here as a fixed case.
constexpr std::initializer_list<std::uint64_t> kRegressionSeeds = {};
constexpr int kIterations = 1500;  // textures per property
constexpr int kLookupsPerTexture = 200;

float fl(L x) { return static_cast<float>(x); }

// Correctly rounded w * d + a: the long double sum r plus its exact error e; only a tie of r
// between two floats needs e to decide (|e| <= half an ulp of r).
float fusedModel(float w, float d, float a) {
  const L p = static_cast<L>(w) * d;  // exact: 24 + 24 bits
  const L r = p + a;
  const L bb = r - p;
  const L e = (p - (r - bb)) + (static_cast<L>(a) - bb);  // TwoSum
  const float f = fl(r);
  if (static_cast<L>(f) == r || e == 0) return f;
  const float g = std::nextafter(f, r > f ? INFINITY : -INFINITY);
  const L mid = (static_cast<L>(f) + g) / 2;  // exact
  if (r != mid) return f;
  return (e > 0) == (g > f) ? g : f;
}

float lerpModel(const PrecisionProfile& p, float w, float a, float b) {
  const float d = fl(static_cast<L>(b) - a);
  if (p.floatLerp == LerpArithmetic::Fused) return fusedModel(w, d, a);
  return fl(static_cast<L>(a) + fl(static_cast<L>(w) * d));
}

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}
std::int64_t floorMod(std::int64_t a, std::int64_t b) { return a - b * floorDiv(a, b); }

struct Texture {
  ref::Dims3 dims;
  ref::TexelFormat format;
  std::vector<std::uint32_t> codes;
  ref::SamplerState sampler;
};

// The texel value as the header states it: unorm k * fl(1 / (2^b - 1)), binary16 exactly, binary32.
float texelValueModel(const Texture& t, std::uint32_t code) {
  switch (t.format) {
    case ref::TexelFormat::R8:
    case ref::TexelFormat::RGBA8:
      return fl(static_cast<L>(code) * fl(1.0L / 255));
    case ref::TexelFormat::R16:
      return fl(static_cast<L>(code) * fl(1.0L / 65535));
    case ref::TexelFormat::R16F: {
      const int e = static_cast<int>((code >> 10) & 31);
      const int m = static_cast<int>(code & 1023);
      const L mag = e == 0 ? std::ldexp(static_cast<L>(m), -24) : std::ldexp(static_cast<L>(1024 + m), e - 25);
      return fl((code & 0x8000u) ? -mag : mag);
    }
    case ref::TexelFormat::R32F:
      return std::bit_cast<float>(code);
  }
  return 0.0f;
}

bool isUnorm(ref::TexelFormat f) { return f != ref::TexelFormat::R16F && f != ref::TexelFormat::R32F; }

float texelModel(const Texture& t, std::int64_t x, std::int64_t y, std::int64_t z) {
  if (x < 0 || y < 0 || z < 0 || x >= t.dims[0] || y >= t.dims[1] || z >= t.dims[2]) {
    const float b = static_cast<float>(t.sampler.borderRed);
    return isUnorm(t.format) ? std::min(std::max(b, 0.0f), 1.0f) : b;
  }
  return texelValueModel(t, t.codes[static_cast<std::size_t>(x + t.dims[0] * (y + t.dims[1] * z))]);
}

struct AxisF {
  std::int64_t i0, i1;
  float w;
};

AxisF floatAxisModel(ref::Wrap wrap, float s, int n) {
  const float c = fl(static_cast<L>(s) * n);
  AxisF a{};
  float u = 0.0f;
  if (wrap == ref::Wrap::ClampToEdge) {  // c = max(min(u N, N) - 0.5, 0)
    u = std::max(fl(static_cast<L>(std::min(c, static_cast<float>(n))) - 0.5L), 0.0f);
  } else {
    u = fl(static_cast<L>(c) - 0.5L);
  }
  const L f = std::floor(static_cast<L>(u));
  a.w = fl(static_cast<L>(u) - f);
  a.i0 = static_cast<std::int64_t>(f);
  a.i1 = a.i0 + 1;
  if (wrap == ref::Wrap::ClampToEdge) a.i1 = std::min<std::int64_t>(a.i1, n - 1);
  if (wrap == ref::Wrap::Repeat) {
    a.i0 = floorMod(a.i0, n);
    a.i1 = floorMod(a.i1, n);
  }
  return a;
}

struct AxisQ {
  std::int64_t i0, i1, w;
};

// s' = RNE(fl(s * 256 N)) - 128, i0 = floor(s' / 256), w = s' mod 256; then wrap/clamp i0, i0 + 1.
AxisQ aosAxisModel(ref::Wrap wrap, float s, int n) {
  const L scaled = fl(static_cast<L>(s) * (256 * n));
  const L fl0 = std::floor(scaled);
  const L frac = scaled - fl0;
  auto k = static_cast<std::int64_t>(fl0);
  if (frac > 0.5L || (frac == 0.5L && floorMod(k, 2) == 1)) ++k;
  const std::int64_t sp = k - 128;
  AxisQ a{floorDiv(sp, 256), 0, floorMod(sp, 256)};
  a.i1 = a.i0 + 1;
  if (wrap == ref::Wrap::Repeat) {
    a.i0 = floorMod(a.i0, n);
    a.i1 = floorMod(a.i1, n);
  } else {
    a.i0 = std::clamp<std::int64_t>(a.i0, 0, n - 1);
    a.i1 = std::clamp<std::int64_t>(a.i1, 0, n - 1);
  }
  return a;
}

float sampleModel(const Texture& t, const PrecisionProfile& p, float s, float tt, float r) {
  const bool aos = p.aos8BitSampling && ref::unormBits(t.format) == 8 && t.sampler.wrap != ref::Wrap::ClampToBorder;
  if (t.sampler.filter == ref::Filter::Nearest) {  // CLAMP_TO_EDGE only: clamp(floor(fl(u N)))
    auto idx = [](float u, int n) {
      return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(static_cast<L>(fl(static_cast<L>(u) * n)))),
                                      0, n - 1);
    };
    return texelModel(t, idx(s, t.dims[0]), idx(tt, t.dims[1]), idx(r, t.dims[2]));
  }
  if (aos) {
    const AxisQ ax = aosAxisModel(t.sampler.wrap, s, t.dims[0]), ay = aosAxisModel(t.sampler.wrap, tt, t.dims[1]),
                az = aosAxisModel(t.sampler.wrap, r, t.dims[2]);
    auto code = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
      return static_cast<std::int64_t>(t.codes[static_cast<std::size_t>(x + t.dims[0] * (y + t.dims[1] * z))]);
    };
    auto lerp8 = [](std::int64_t w, std::int64_t a, std::int64_t b) { return a + floorDiv(w * (b - a) + 128, 256); };
    auto slice = [&](std::int64_t z) {
      return lerp8(ay.w, lerp8(ax.w, code(ax.i0, ay.i0, z), code(ax.i1, ay.i0, z)),
                   lerp8(ax.w, code(ax.i0, ay.i1, z), code(ax.i1, ay.i1, z)));
    };
    return texelValueModel(t, static_cast<std::uint32_t>(lerp8(az.w, slice(az.i0), slice(az.i1))));
  }
  const AxisF ax = floatAxisModel(t.sampler.wrap, s, t.dims[0]), ay = floatAxisModel(t.sampler.wrap, tt, t.dims[1]),
              az = floatAxisModel(t.sampler.wrap, r, t.dims[2]);
  auto slice = [&](std::int64_t z) {
    return lerpModel(p, ay.w, lerpModel(p, ax.w, texelModel(t, ax.i0, ay.i0, z), texelModel(t, ax.i1, ay.i0, z)),
                     lerpModel(p, ax.w, texelModel(t, ax.i0, ay.i1, z), texelModel(t, ax.i1, ay.i1, z)));
  };
  return lerpModel(p, az.w, slice(az.i0), slice(az.i1));
}

// A float whose magnitude lies in [2^-20, 4) or is zero: no denormals anywhere in the lerps.
float randomFloatTexel(Rng& rng) {
  if (coin(rng, 5)) return 0.0f;
  const float m = static_cast<float>(1.0 + uniformUnit(rng));
  const float v = std::ldexp(m, static_cast<int>(uniformInt(rng, -20, 1)));
  return coin(rng, 30) ? -v : v;
}

Texture randomTexture(Rng& rng, ref::Filter filter, ref::Wrap wrap) {
  Texture t;
  const ref::TexelFormat formats[] = {ref::TexelFormat::R8, ref::TexelFormat::RGBA8, ref::TexelFormat::R16,
                                      ref::TexelFormat::R16F, ref::TexelFormat::R32F};
  t.format = formats[uniformInt(rng, 0, 4)];
  for (int& d : t.dims)
    d = wrap == ref::Wrap::Repeat ? 1 << uniformInt(rng, 0, 5) : static_cast<int>(uniformInt(rng, 1, 40));
  t.sampler = {filter, wrap, coin(rng, 50) ? uniformUnit(rng) * 1.5 - 0.25 : 0.0};
  t.codes.resize(static_cast<std::size_t>(t.dims[0]) * t.dims[1] * t.dims[2]);
  const bool smooth = coin(rng, 50);  // smooth data makes small b - a, noise makes large ones
  std::uint32_t prev = 0;
  for (std::uint32_t& c : t.codes) {
    switch (t.format) {
      case ref::TexelFormat::R8:
      case ref::TexelFormat::RGBA8:
        c = smooth ? static_cast<std::uint32_t>(std::clamp<std::int64_t>(prev + uniformInt(rng, -3, 3), 0, 255))
                   : static_cast<std::uint32_t>(uniformInt(rng, 0, 255));
        break;
      case ref::TexelFormat::R16:
        c = smooth ? static_cast<std::uint32_t>(std::clamp<std::int64_t>(prev + uniformInt(rng, -300, 300), 0, 65535))
                   : static_cast<std::uint32_t>(uniformInt(rng, 0, 65535));
        break;
      case ref::TexelFormat::R16F: {  // finite, normal or zero
        const std::uint32_t e = static_cast<std::uint32_t>(uniformInt(rng, 1, 30)),
                            m = static_cast<std::uint32_t>(uniformInt(rng, 0, 1023));
        c = coin(rng, 5) ? 0u : ((coin(rng, 30) ? 0x8000u : 0u) | (e << 10) | m);
        break;
      }
      case ref::TexelFormat::R32F:
        c = std::bit_cast<std::uint32_t>(randomFloatTexel(rng));
        break;
    }
    prev = c;
  }
  return t;
}

// Coordinates in [-0.25, 1.25], a third of them on or a few ulps beside a texel boundary k / n or a
// texel centre (k + 0.5) / n, some exactly 0 or 1.
float randomCoord(Rng& rng, int n) {
  const int kind = static_cast<int>(uniformInt(rng, 0, 9));
  if (kind == 0) return coin(rng, 50) ? 0.0f : 1.0f;
  if (kind <= 3) {
    const double k = static_cast<double>(uniformInt(rng, -1, 2 * n + 1)) / 2.0;
    float c = static_cast<float>(k / n);
    for (auto steps = uniformInt(rng, -3, 3); steps != 0; steps += steps > 0 ? -1 : 1)
      c = std::nextafter(c, steps > 0 ? INFINITY : -INFINITY);
    return c;
  }
  return static_cast<float>(uniformUnit(rng) * 1.5 - 0.25);
}

void checkLookups(ref::Filter filter, ref::Wrap wrap, bool llvmpipeOnly) {
  property::forEachSeed(kIterations, kRegressionSeeds, [&](Rng& rng) {
    const Texture t = randomTexture(rng, filter, wrap);
    for (const PrecisionProfile& p : knownProfiles()) {
      if (llvmpipeOnly && p.sampler != SamplerFamily::Llvmpipe) continue;
      const TextureSamplerEmu emu(t.dims, t.format, t.codes, t.sampler, p);
      for (int i = 0; i < kLookupsPerTexture / 5; ++i) {
        const float s = randomCoord(rng, t.dims[0]), tt = randomCoord(rng, t.dims[1]), r = randomCoord(rng, t.dims[2]);
        const float got = emu.sampleRed(s, tt, r), want = sampleModel(t, p, s, tt, r);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(got), std::bit_cast<std::uint32_t>(want))
            << p.name << " " << ref::name(t.format) << " " << t.dims[0] << "x" << t.dims[1] << "x" << t.dims[2]
            << " at (" << std::hexfloat << s << ", " << tt << ", " << r << "): emulation " << got << ", model " << want;
      }
    }
  });
}

TEST(SamplingProperty, LinearClampToEdgeIsBitExactAgainstTheModel) {
  checkLookups(ref::Filter::Linear, ref::Wrap::ClampToEdge, true);
}
TEST(SamplingProperty, LinearRepeatPowerOfTwoIsBitExactAgainstTheModel) {
  checkLookups(ref::Filter::Linear, ref::Wrap::Repeat, true);
}
TEST(SamplingProperty, LinearClampToBorderIsBitExactAgainstTheModel) {
  checkLookups(ref::Filter::Linear, ref::Wrap::ClampToBorder, true);
}
TEST(SamplingProperty, NearestClampToEdgeIsBitExactAgainstTheModel) {
  checkLookups(ref::Filter::Nearest, ref::Wrap::ClampToEdge, true);
}

}  // namespace sampling_property_test
}  // namespace voxref::emu
