// Properties of the framebuffer side (float32.h conversions, framebuffer_emu.h BlendEmu), each
// against an independent model: exact rational rounding on the float's integer mantissa, a binary
// search over the binary16 codes, and integer / long double accumulation with every float32
// rounding made explicit (sums rounded to long double and then to float are correctly rounded).
//
//   floatToUnormHalfEven  bit-exact: clamp, RNE(fl(x (2^b - 1))), NaN -> 0 (float32.h)
//                          and within 1 code of ref::unormFromDouble (one rounding, no float step),
//                          differing only where x (2^b - 1) is within one float ulp of a tie
//   floatToUnormHalfUp     bit-exact: trunc(fl(fl(clamp(x) 65535) + 0.5))
//   floatToHalfTowardZero  bit-exact: the largest binary16 not above |x| (65504 on overflow)
//   BlendEmu ONE/ONE       bit-exact per framebuffer_emu.h: saturating integer accumulation of
//                          per-pass codes (unorm 8/12/16, QuantizePerPass), float32 + RTZ half
//                          (RGBA16F), float32 (RGBA32F), and softpipe's clamped float tile with or
//                          without a flush after every pass.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "emulation/float32.h"
#include "emulation/framebuffer_emu.h"
#include "emulation/profile.h"
#include "reference/common/rounding.h"
#include "tests/property/property_seed.h"

namespace voxref::emu {
namespace blending_property_test {  // named: a unity build compiles several test files together

using property::coin;
using property::Rng;
using property::uniformInt;
using property::uniformUnit;
using L = long double;

constexpr std::initializer_list<std::uint64_t> kRegressionSeeds = {};
constexpr int kIterations = 10000;

float fl(L x) { return static_cast<float>(x); }

// Round half to even of a non-negative float, exactly: p = m 2^e with an integer m < 2^24.
std::int64_t roundHalfEvenExact(float p) {
  if (p < 0.5f) return 0;
  int e = 0;
  const float frac = std::frexp(p, &e);  // p = frac 2^e, frac in [0.5, 1)
  const auto m = static_cast<std::int64_t>(std::ldexp(frac, 24));
  const int shift = 24 - e;  // p = m / 2^shift
  if (shift <= 0) return m << -shift;
  const std::int64_t q = m >> shift, rem = m & ((std::int64_t{1} << shift) - 1), half = std::int64_t{1} << (shift - 1);
  return (rem > half || (rem == half && (q & 1))) ? q + 1 : q;
}

std::uint32_t unormHalfEvenModel(float x, int bits) {
  if (std::isnan(x)) return 0;
  const float c = std::min(std::max(x, 0.0f), 1.0f);
  const float p = fl(static_cast<L>(c) * ((std::int64_t{1} << bits) - 1));
  return static_cast<std::uint32_t>(roundHalfEvenExact(p));
}

std::uint32_t unormHalfUpModel(float x) {
  const float c = x > 0.0f ? (x > 1.0f ? 1.0f : x) : 0.0f;
  const float p = fl(static_cast<L>(c) * 65535);
  return static_cast<std::uint32_t>(std::trunc(static_cast<L>(fl(static_cast<L>(p) + 0.5L))));
}

L halfValue(std::uint16_t h) {
  const int e = (h >> 10) & 31, m = h & 1023;
  const L mag = e == 0 ? std::ldexp(static_cast<L>(m), -24) : std::ldexp(static_cast<L>(1024 + m), e - 25);
  return (h & 0x8000u) ? -mag : mag;
}

// The largest finite binary16 whose magnitude does not exceed |x|, with x's sign.
std::uint16_t halfTowardZeroModel(float x) {
  const L a = std::fabs(static_cast<L>(x));
  std::uint16_t lo = 0, hi = 0x7bff;
  while (lo < hi) {
    const auto mid = static_cast<std::uint16_t>((lo + hi + 1) / 2);
    if (halfValue(mid) <= a)
      lo = mid;
    else
      hi = static_cast<std::uint16_t>(mid - 1);
  }
  return static_cast<std::uint16_t>(lo | (std::signbit(x) ? 0x8000u : 0u));
}

// Values that stress the conversions: uniform in [-0.25, 1.25], exact ties (k + 0.5) / (2^b - 1) as
// floats and their neighbours, huge and tiny magnitudes.
float randomSource(Rng& rng, int bits) {
  const int kind = static_cast<int>(uniformInt(rng, 0, 9));
  if (kind <= 3) {
    const double maxCode = static_cast<double>((std::int64_t{1} << bits) - 1);
    float v = static_cast<float>((static_cast<double>(uniformInt(rng, 0, static_cast<std::int64_t>(maxCode))) + 0.5) /
                                 maxCode);
    for (auto steps = uniformInt(rng, -2, 2); steps != 0; steps += steps > 0 ? -1 : 1)
      v = std::nextafter(v, steps > 0 ? INFINITY : -INFINITY);
    return v;
  }
  if (kind == 4)
    return static_cast<float>(std::ldexp(1.0 + uniformUnit(rng), static_cast<int>(uniformInt(rng, -30, 20)))) *
           (coin(rng, 30) ? -1.0f : 1.0f);
  if (kind == 5) return coin(rng, 50) ? 0.0f : 1.0f;
  return static_cast<float>(uniformUnit(rng) * 1.5 - 0.25);
}

TEST(BlendingProperty, UnormHalfEvenIsTheExactRationalRoundingOfTheFloatProduct) {
  property::forEachSeed(kIterations, kRegressionSeeds, [&](Rng& rng) {
    for (int i = 0; i < 50; ++i) {
      const int bits = static_cast<int>(uniformInt(rng, 1, 16));
      const float x = randomSource(rng, bits);
      const std::uint32_t got = floatToUnormHalfEven(x, bits);
      ASSERT_EQ(got, unormHalfEvenModel(x, bits)) << "bits " << bits << " x " << std::hexfloat << x;
      // Against one exact rounding of the real product (no float step): within 1 code, and only
      // where the exact product lies within one float ulp of a tie.
      const std::uint32_t ideal = ref::unormFromDouble(x, bits);
      const auto diff = static_cast<std::int64_t>(got) - static_cast<std::int64_t>(ideal);
      ASSERT_LE(std::abs(diff), 1) << "bits " << bits << " x " << std::hexfloat << x;
      if (diff != 0) {
        const L exact = static_cast<L>(std::clamp(x, 0.0f, 1.0f)) * ((std::int64_t{1} << bits) - 1);
        const L tie = std::floor(exact) + 0.5L;
        const float p = fl(exact);
        const L ulp = static_cast<L>(std::nextafter(p, INFINITY)) - p;
        ASSERT_LE(std::fabs(exact - tie), ulp) << "bits " << bits << " x " << std::hexfloat << x;
      }
    }
  });
}

TEST(BlendingProperty, UnormHalfUpAndHalfTowardZeroMatchTheirModels) {
  property::forEachSeed(kIterations, kRegressionSeeds, [&](Rng& rng) {
    for (int i = 0; i < 50; ++i) {
      const float x = randomSource(rng, 16);
      ASSERT_EQ(floatToUnormHalfUp(x, 16), unormHalfUpModel(x)) << std::hexfloat << x;
      // Any finite float, including denormal binary16 results and overflow.
      const float y =
          coin(rng, 50)
              ? x * 70000.0f
              : std::bit_cast<float>(static_cast<std::uint32_t>(uniformInt(rng, 0, 0xff7fffff)) & 0xff7fffffu);
      ASSERT_EQ(floatToHalfTowardZero(y), halfTowardZeroModel(y)) << std::hexfloat << y;
    }
  });
}

// N draws of ONE / ONE blending onto a cleared pixel, each FUNC_ADD or FUNC_REVERSE_SUBTRACT.
TEST(BlendingProperty, OneOneAccumulationMatchesTheModelOfEveryFormatAndProfile) {
  const ref::FramebufferFormat formats[] = {ref::FramebufferFormat::RGBA8, ref::FramebufferFormat::RGBA12,
                                            ref::FramebufferFormat::RGBA16, ref::FramebufferFormat::RGBA16F,
                                            ref::FramebufferFormat::RGBA32F};
  property::forEachSeed(kIterations, kRegressionSeeds, [&](Rng& rng) {
    const auto profiles = knownProfiles();
    const PrecisionProfile& profile =
        profiles[static_cast<std::size_t>(uniformInt(rng, 0, static_cast<std::int64_t>(profiles.size()) - 1))];
    const ref::FramebufferFormat format = formats[uniformInt(rng, 0, 4)];
    const bool flushEachPass = coin(rng, 30);
    const BlendEmu emu(format, profile, flushEachPass, 64, 64);
    const int bits = ref::unormBits(format);
    const bool perPass =
        format == ref::FramebufferFormat::RGBA12 || profile.framebuffer == FramebufferModel::QuantizePerPass;
    const int passes = static_cast<int>(uniformInt(rng, 1, 40));
    const int addPercent = static_cast<int>(uniformInt(rng, 50, 100));

    PixelState px = emu.cleared();
    std::int64_t code = 0;  // per-pass model
    float tile = 0.0f;      // softpipe tile model
    for (int i = 0; i < passes; ++i) {
      // Small sources so that sums stay inside [0, 1] for a while before they saturate.
      float src = randomSource(rng, bits ? bits : 8);
      if (coin(rng, 60)) src = fl(static_cast<L>(src) / static_cast<L>(uniformInt(rng, 2, 40)));
      const bool add = coin(rng, addPercent);
      emu.blend(px, src, add ? ref::BlendEquation::FuncAdd : ref::BlendEquation::FuncReverseSubtract);
      if (perPass) {
        if (bits) {
          const std::int64_t s = unormHalfEvenModel(src, bits), maxCode = (std::int64_t{1} << bits) - 1;
          code = add ? std::min(code + s, maxCode) : std::max<std::int64_t>(code - s, 0);
        } else if (format == ref::FramebufferFormat::RGBA16F) {
          const L d = halfValue(static_cast<std::uint16_t>(code));
          code = halfTowardZeroModel(fl(add ? src + d : d - src));
        } else {  // RGBA32F (sources are normal and sums of them never denormal here)
          const float d = std::bit_cast<float>(static_cast<std::uint32_t>(code));
          code = std::bit_cast<std::uint32_t>(fl(add ? static_cast<L>(src) + d : static_cast<L>(d) - src));
        }
      } else {
        auto clampUnit = [](float x) { return x > 0.0f ? (x > 1.0f ? 1.0f : x) : 0.0f; };
        const float s = bits ? clampUnit(src) : src;
        float r = fl(add ? static_cast<L>(s) + tile : static_cast<L>(tile) - s);
        if (bits) r = clampUnit(r);
        if (flushEachPass && format != ref::FramebufferFormat::RGBA32F) {
          if (bits == 8)
            r = fl(static_cast<L>(unormHalfEvenModel(r, 8)) * fl(1.0L / 255));
          else if (bits == 16)
            r = fl(static_cast<L>(unormHalfUpModel(r)) * fl(1.0L / 65535));
          else
            r = fl(halfValue(halfTowardZeroModel(r)));
        }
        tile = r;
      }
    }
    std::int64_t want = code;
    if (!perPass) {
      if (bits == 8)
        want = unormHalfEvenModel(tile, 8);
      else if (bits == 16)
        want = profile.unorm16Store == UnormRounding::HalfUp ? unormHalfUpModel(tile) : unormHalfEvenModel(tile, 16);
      else if (format == ref::FramebufferFormat::RGBA16F)
        want = halfTowardZeroModel(tile);
      else
        want = std::bit_cast<std::uint32_t>(tile);
    }
    ASSERT_EQ(emu.resolve(px), static_cast<std::uint32_t>(want))
        << profile.name << " " << ref::name(format) << (flushEachPass ? " flush each pass" : "") << " after " << passes
        << " passes";
  });
}

}  // namespace blending_property_test
}  // namespace voxref::emu
