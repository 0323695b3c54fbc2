#include "emulation/timevarying_envelope.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "emulation/float32.h"
#include "emulation/interval_arithmetic.h"
#include "emulation/profile.h"
#include "emulation/timevarying_emu.h"
#include "reference/timevarying/plume.h"

namespace voxref::emu {
namespace {

// Exact rational arithmetic on dyadic numbers: every value below is a float32 or a product of two,
__extension__ typedef __int128 Int128;  // exact fixed point for the quotient checks (GCC and Clang)

// so it is an integer multiple of 2^-kScale small enough for Int128.
constexpr int kScale = 80;
Int128 fixed(double v) {
  const long double s = std::ldexp(static_cast<long double>(v), kScale);
  EXPECT_EQ(s, std::floor(s)) << v << " is not a multiple of 2^-" << kScale;
  return static_cast<Int128>(s);
}

// dEQP's ULP of the exact quotient x / y (x, y > 0), derived independently of ulpF32: the binade
// e with 2^e <= x / y < 2^(e+1) is found by exact comparisons x >= 2^e y.
double exactQuotientUlp(double x, double y) {
  int e = std::ilogb(x) - std::ilogb(y) - 2;                       // below the binade: x / y >= 2^e
  while (fixed(x) >= fixed(std::ldexp(y, e + 1)) && e < 127) ++e;  // x / y >= 2^(e+1)
  const bool powerOfTwo = fixed(x) == fixed(std::ldexp(y, e));
  return std::ldexp(1.0, (powerOfTwo ? e - 1 : e) - 23);
}

// Is float f within 2.5 ULP of x / y? |f y - x| <= 2.5 u y, decided in integers.
bool allowedQuotient(float f, double x, double y, double u) {
  const Int128 d = fixed(static_cast<double>(f) * y) - fixed(x);
  const Int128 bound = fixed(2.5 * u * y);
  return d <= bound && -d <= bound;
}

// Every float32 division result allowed for x / y, found by walking outward from x / y.
std::vector<float> allowedQuotients(float x, float y) {
  const double u = exactQuotientUlp(x, y);
  std::vector<float> out;
  const float start = static_cast<float>(static_cast<double>(x) / y);
  for (float f = start; allowedQuotient(f, x, y, u); f = std::nextafter(f, -INFINITY)) out.insert(out.begin(), f);
  for (float f = std::nextafter(start, INFINITY); allowedQuotient(f, x, y, u); f = std::nextafter(f, INFINITY))
    out.push_back(f);
  return out;
}

TEST(IntervalArithmetic, UlpIsDeqpsWithHarrisonAtPowersOfTwo) {
  EXPECT_EQ(ulpF32(1.5), std::ldexp(1.0, -23));
  EXPECT_EQ(ulpF32(1.0), std::ldexp(1.0, -24));  // the spacing below 1
  EXPECT_EQ(ulpF32(3.0), std::ldexp(1.0, -22));
  EXPECT_EQ(ulpF32(0.0), std::ldexp(1.0, -149));
}

TEST(IntervalArithmetic, CorrectlyRoundedOperationsGiveEitherNeighbourOrTheExactValue) {
  const Interval exact = addF32({0.25, 0.25}, {0.5, 0.5});
  EXPECT_EQ(exact.lo, 0.75);
  EXPECT_EQ(exact.hi, 0.75);
  // 1 + 2^-30 is not a float32: the two neighbours 1 and 1 + 2^-23.
  const Interval r = addF32({1.0, 1.0}, {std::ldexp(1.0, -30), std::ldexp(1.0, -30)});
  EXPECT_EQ(r.lo, 1.0);
  EXPECT_EQ(r.hi, 1.0 + std::ldexp(1.0, -23));
  // fl(1/3) = 11184811 2^-25, so fl(1/3) * 3 = 1 + 2^-25 exactly: neighbours 1 and 1 + 2^-23.
  const double third = 1.0f / 3.0f;
  ASSERT_EQ(third, 11184811 * std::ldexp(1.0, -25));
  const Interval m = mulF32({third, third}, {3.0, 3.0});
  EXPECT_EQ(m.lo, 1.0);
  EXPECT_EQ(m.hi, 1.0 + std::ldexp(1.0, -23));
}

TEST(IntervalArithmetic, DivisionAndModAgainstExactRationalsAtWorstPoints) {
  const float third = 1.0f / 3.0f, step255 = 1.0f / 255.0f;
  struct Case {
    float x, y;
  };
  std::vector<Case> cases;
  for (float y : {third, step255, 0.25f, 0.125f})
    for (int k : {1, 2, 3, 7, 100}) {
      const float multiple = static_cast<float>(k) * y;  // fl(k y): just below, on or above k y
      for (float x : {std::nextafter(multiple, 0.0f), multiple, std::nextafter(multiple, 2.0f * multiple),
                      std::nextafter(std::nextafter(multiple, 2.0f * multiple), 2.0f * multiple)})
        cases.push_back({x, y});
    }
  int straddling = 0;
  for (const Case& c : cases) {
    const std::vector<float> allowed = allowedQuotients(c.x, c.y);
    ASSERT_FALSE(allowed.empty());
    const Interval q = divF32({c.x, c.x}, {c.y, c.y}, 2.5);
    // Sound: every allowed quotient inside; tight: at most one float32 more on either side.
    EXPECT_LE(q.lo, allowed.front()) << c.x << " / " << c.y;
    EXPECT_GE(q.hi, allowed.back()) << c.x << " / " << c.y;
    EXPECT_GE(q.lo, std::nextafter(allowed.front(), -INFINITY)) << c.x << " / " << c.y;
    EXPECT_LE(q.hi, std::nextafter(allowed.back(), INFINITY)) << c.x << " / " << c.y;
    // mod: one branch per floor value of an allowed quotient, each holding x - y k correctly rounded.
    std::set<double> floors;
    for (float f : allowed) floors.insert(std::floor(f));
    const std::vector<Interval> branches = modF32({c.x, c.x}, {c.y, c.y}, 2.5);
    ASSERT_GE(branches.size(), floors.size()) << c.x << " mod " << c.y;
    ASSERT_LE(branches.size(), floors.size() + 1) << c.x << " mod " << c.y;
    straddling += floors.size() > 1;
    for (double k : floors) {
      // x - y k exactly (dyadic), then its float32 neighbours.
      const Int128 exact = fixed(c.x) - fixed(static_cast<double>(c.y) * k);
      const long double value = std::ldexp(static_cast<long double>(exact), -kScale);
      const double below = float32Below(static_cast<double>(value)), above = float32Above(static_cast<double>(value));
      const bool found = std::any_of(branches.begin(), branches.end(), [&](const Interval& b) {
        return b.lo <= below && b.hi >= above && fixed(b.lo) <= exact && fixed(b.hi) >= exact;
      });
      EXPECT_TRUE(found) << c.x << " mod " << c.y << ", floor " << k;
    }
  }
  // x = fl(k y) for k y not representable lies within 2.5 ULP of an integer quotient: both branches.
  EXPECT_GT(straddling, 10);
  // The textbook case: mod(3 fl(1/3), fl(1/3)) may be about 0 or about 1/3.
  const std::vector<Interval> m = modF32({3.0f * third, 3.0f * third}, {third, third}, 2.5);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[0].hi, third, 1e-6);
  EXPECT_NEAR(m[1].lo, 0.0, 1e-6);
}

TEST(IntervalArithmetic, UnormConversionsAllowMesasReciprocalAndEitherCode) {
  for (int bits : {8, 16}) {
    const std::uint32_t max = (1u << bits) - 1u;
    for (std::uint32_t c = 0; c <= max; ++c) {
      const Interval v = unormToFloatF32(c, bits, 2.5);
      const double mesa = unormToFloat(c, bits);  // c * fl(1 / (2^b - 1)): up to 1.25 ULP off
      ASSERT_TRUE(v.contains(mesa)) << bits << " bits, code " << c;
      if (bits == 8) {
        const Interval codes = unormCodes(v, 8);
        ASSERT_LE(codes.lo, c);
        ASSERT_GE(codes.hi, c);
        ASSERT_LE(codes.hi - codes.lo, 2.0);  // either side of c / 255: c - 1 .. c + 1
      }
    }
    EXPECT_EQ(unormToFloatF32(max, bits, 2.5).lo, 1.0);  // exact: `alpha == 1.0` is decided
    EXPECT_EQ(unormToFloatF32(0, bits, 2.5).hi, 0.0);
  }
  const Interval half = unormCodes({0.5, 0.5}, 8);  // 127.5: either closest code
  EXPECT_EQ(half.lo, 127);
  EXPECT_EQ(half.hi, 128);
  const Interval clamped = unormCodes({-0.25, 1.5}, 8);
  EXPECT_EQ(clamped.lo, 0);
  EXPECT_EQ(clamped.hi, 255);
}

// The frames of the built-in cases (conformance/modules/timevarying/timevarying_scene.cpp), at `side`.
std::vector<ref::PlaneFrame> builtInFrames(int side, int blockSide, int cells) {
  const double h = 1.0 / side, b = h * blockSide;
  return {ref::explicitFrame({0, 0, 0}, {h, 0, 0}, {0, h, 0}, {0, 0, h}, side, side, side),
          ref::explicitFrame(glm::dvec3(-h / 2), {h, 0, 0}, {0, h, 0}, {0, 0, h}, side, side, side),
          ref::explicitFrame({-b / 2, 0, 0}, {b, 0, 0}, {0, h, 0}, {0, 0, h}, cells, side, side),
          ref::explicitFrame({1.0 - h / 2, 0, 0}, {h, 0, 0}, {0, h, 0}, {0, 0, h}, 1, side, side),
          ref::orbitFrame(30.0, 20.0, 24, 24, 20)};
}

struct Config {
  ref::DecoderVariant decoder;
  ref::IndexEncoding encoding;
};
const Config kConfigs[] = {{ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedRgba8},
                           {ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedRgba16},
                           {ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedFloat},
                           {ref::DecoderVariant::TexelCentre, ref::IndexEncoding::BlockRgba8},
                           {ref::DecoderVariant::TexelFetch, ref::IndexEncoding::BlockRgba8}};

std::size_t countTier(const std::vector<std::uint8_t>& tiers, int tier) {
  return static_cast<std::size_t>(std::count(tiers.begin(), tiers.end(), tier));
}

TEST(TimeVaryingEnvelope, ContainsEveryProfilesEmulationOnTheBuiltInScenes) {
  // The soundness check: the drivers' models lie inside the pass envelope, decode and composite.
  const ref::TimeSeries series = ref::driftingBlobs(16, 3);
  const ref::TransferFunction tf = ref::transferFunction("gray");
  for (const Config& c : kConfigs) {
    const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(series, tf, {2, c.encoding});
    const TimeVaryingEnvelope envelope(tex, c.decoder);
    const auto frames = builtInFrames(16, tex.layout.blockSide, tex.layout.cells);
    for (const PrecisionProfile& profile : knownProfiles())
      for (int step = 0; step < 3; ++step) {
        for (const ref::PlaneFrame& f : frames) {
          const EmulatedDecode d = emulateDecodePlanes(tex, c.decoder, step, f, profile);
          ASSERT_EQ(countTier(envelopeTiers(envelope, step, f, false, d.colours), 0), d.colours.colours.size())
              << ref::name(c.decoder) << " " << ref::name(c.encoding) << " " << profile.name << " step " << step;
        }
        const ref::RgbaStack composite = emulateComposite(tex, c.decoder, step, frames.back(), profile);
        ASSERT_EQ(countTier(envelopeTiers(envelope, step, frames.back(), true, composite), 0), composite.colours.size())
            << "composite " << ref::name(c.decoder) << " " << profile.name << " step " << step;
      }
  }
}

// With llvmpipe's measured blending (mulnorm, nearest stores: docs/probe.md) the composite envelope
// holds llvmpipe's emulation and is never wider than the spec's; softpipe, whose float tile cache
// blends in float (no per-pass store), leaves it: the measured rule can fail.
TEST(TimeVaryingEnvelope, MeasuredBlendingHoldsItsDriverAndFailsAnotherFormula) {
  const ref::TimeSeries series = ref::driftingBlobs(16, 3);
  const ref::TransferFunction tf = ref::transferFunction("gray");
  MeasuredArithmetic mulnorm;
  mulnorm.requantizedPasses = true;
  mulnorm.unorm8Store = MeasuredArithmetic::Store::Nearest;
  mulnorm.srcAlphaBlend = MeasuredArithmetic::Blend::Mulnorm;
  std::size_t outsideSoftpipe = 0;
  for (const Config& c : kConfigs) {
    const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(series, tf, {2, c.encoding});
    const TimeVaryingEnvelope spec(tex, c.decoder), measured(tex, c.decoder, mulnorm);
    EXPECT_EQ(measured.basis(), "measured nearest 8-bit stores, measured mulnorm blending");
    const ref::PlaneFrame f = builtInFrames(16, tex.layout.blockSide, tex.layout.cells).back();
    const ref::RgbaStack composite = emulateComposite(tex, c.decoder, 1, f, *findProfile("llvmpipe"));
    std::vector<std::uint8_t> specWidths, measuredWidths;
    (void)envelopeTiers(spec, 1, f, true, composite, 0, &specWidths);
    ASSERT_EQ(countTier(envelopeTiers(measured, 1, f, true, composite, 0, &measuredWidths), 0),
              composite.colours.size())
        << ref::name(c.decoder);
    for (std::size_t i = 0; i < specWidths.size(); ++i) ASSERT_LE(measuredWidths[i], specWidths[i]);
    const ref::RgbaStack soft = emulateComposite(tex, c.decoder, 1, f, *findProfile("softpipe"));
    outsideSoftpipe += soft.colours.size() - countTier(envelopeTiers(measured, 1, f, true, soft), 0);
  }
  EXPECT_GT(outsideSoftpipe, 0u);
}

TEST(TimeVaryingEnvelope, ContainsTheLiteralAndPaperDecodersOnThePapersLayout) {
  const ref::TimeSeries series = ref::driftingBlobs(128, 2);
  ref::TimeVaryingOptions o{4, ref::IndexEncoding::NormalizedRgba8};
  o.paperLayout = true;
  const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(series, ref::transferFunction("gray"), o);
  const ref::PlaneFrame f = ref::orbitFrame(30.0, 20.0, 32, 32, 12);
  for (ref::DecoderVariant v : {ref::DecoderVariant::Literal, ref::DecoderVariant::Paper}) {
    const TimeVaryingEnvelope envelope(tex, v);
    for (const char* profile : {"llvmpipe", "softpipe"}) {
      const EmulatedDecode d = emulateDecodePlanes(tex, v, 1, f, *findProfile(profile));
      EXPECT_EQ(countTier(envelopeTiers(envelope, 1, f, false, d.colours), 0), d.colours.colours.size())
          << ref::name(v) << " " << profile;
    }
  }
}

TEST(TimeVaryingEnvelope, AnOffByOneTexelDecodeFallsOutside) {
  // Negative control: the texel_fetch decoder reading the refinement texel one to the +x side.
  const ref::TimeSeries series = ref::driftingBlobs(16, 3);
  const ref::TimeVaryingTextures tex =
      ref::encodeTimeVarying(series, ref::transferFunction("gray"), {2, ref::IndexEncoding::BlockRgba8});
  const TimeVaryingEnvelope envelope(tex, ref::DecoderVariant::TexelFetch);
  const ref::PlaneFrame f = builtInFrames(16, tex.layout.blockSide, tex.layout.cells)[0];
  EmulatedDecode d = emulateDecodePlanes(tex, ref::DecoderVariant::TexelFetch, 1, f, *findProfile("llvmpipe"));
  std::size_t differing = 0;
  for (std::size_t i = 0; i < d.samples.size(); ++i) {
    if (!d.samples[i].refined) continue;
    std::array<int, 3> t = d.samples[i].refinementTexel;
    t[0] = std::min(t[0] + 1, tex.refinement.dims[0] - 1);
    const std::uint8_t* wrong =
        &tex.refinement.texels[4 * (t[0] + static_cast<std::size_t>(tex.refinement.dims[0]) *
                                               (t[1] + static_cast<std::size_t>(tex.refinement.dims[1]) * t[2]))];
    ref::Rgba8& c = d.colours.colours[i];
    int diff = 0;
    for (int ch = 0; ch < 4; ++ch) diff = std::max(diff, std::abs(int(c[ch]) - int(wrong[ch])));
    differing += diff >= 2;
    c = {wrong[0], wrong[1], wrong[2], wrong[3]};
  }
  const std::vector<std::uint8_t> tiers = envelopeTiers(envelope, 1, f, false, d.colours);
  ASSERT_GT(differing, 100u);
  EXPECT_EQ(countTier(tiers, 2), differing);  // every colour two codes off is a failure, nothing else
}

TEST(TimeVaryingEnvelope, QualityWarningTierAcceptsAFetchASubtexelStepAcrossAFace) {
  // Samples 1/32 voxel right of the voxel faces x = i (never a cell face): the pass envelope (7
  // subtexel bits, 1/128 texel) reads only voxel i, the quality-warning one (4 bits, 1/16) voxel
  // i - 1 too. A driver returning voxel i - 1 there earns a warning, not a pass or a failure.
  const ref::TimeSeries series = ref::driftingBlobs(16, 1);
  const ref::TimeVaryingTextures tex =
      ref::encodeTimeVarying(series, ref::transferFunction("gray"), {2, ref::IndexEncoding::NormalizedFloat});
  const TimeVaryingEnvelope envelope(tex, ref::DecoderVariant::Paper);
  const double h = 1.0 / 16;
  const ref::PlaneFrame f = ref::explicitFrame({h / 32 - h / 2, 0, 0}, {h, 0, 0}, {0, h, 0}, {0, 0, h}, 16, 16, 16);
  ref::RgbaStack right{16, 16, 16, {}}, left{16, 16, 16, {}};
  std::size_t candidates = 0;
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const ref::Rgba8 r = ref::decodeVoxel(tex, 0, x, y, z);
        right.colours.push_back(r);
        if (x % tex.layout.blockSide == 0) {  // a cell face: keep the right colour
          left.colours.push_back(r);
          continue;
        }
        const ref::Rgba8 l = ref::decodeVoxel(tex, 0, x - 1, y, z);
        int diff = 0;
        for (int ch = 0; ch < 4; ++ch) diff = std::max(diff, std::abs(int(r[ch]) - int(l[ch])));
        candidates += diff >= 2;
        left.colours.push_back(l);
      }
  EXPECT_EQ(countTier(envelopeTiers(envelope, 0, f, false, right), 0), right.colours.size());
  const std::vector<std::uint8_t> tiers = envelopeTiers(envelope, 0, f, false, left);
  ASSERT_GT(candidates, 50u);
  EXPECT_EQ(countTier(tiers, 1), candidates);
  EXPECT_EQ(countTier(tiers, 2), 0u);
}

}  // namespace
}  // namespace voxref::emu
