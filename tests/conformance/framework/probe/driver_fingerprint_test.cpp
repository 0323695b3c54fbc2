#include "conformance/framework/probe/driver_fingerprint.h"

#include <bit>
#include <cmath>
#include <map>
#include <stdexcept>

#include <gtest/gtest.h>

#include "conformance/framework/probe/fingerprint_match.h"
#include "emulation/float32.h"
#include "emulation/probe_emu.h"
#include "emulation/profile.h"

namespace voxref::conf {
namespace {

const ref::ProbeDesign& design() { return ref::probeDesign(); }

std::string valueOf(const DriverFingerprint& fp, std::string_view id) {
  const InferredProperty* p = fp.find(id);
  return p ? p->value : "(missing)";
}

// What each known profile must infer to, stated from the profile's fields (profile.h) by hand: the
// emulator computes the frames, the inference reads them, and this table is the third, independent
// statement of the parameters.
std::map<std::string, std::string> expectedValues(const emu::PrecisionProfile& p) {
  const bool aos = p.aos8BitSampling;
  return {
      {"sampling.unorm8.subtexel_bits", aos ? "8" : "float"},
      {"sampling.unorm8.coordinate_rounding", aos ? "half_even" : "float"},
      {"sampling.unorm8.lerp_rounding", aos ? "nearest" : "float"},
      {"sampling.float.subtexel_bits", "float"},
      {"sampling.float.lerp", p.floatLerp == emu::LerpArithmetic::Fused ? "fused" : "unfused"},
      {"sampling.float.repeat_scaling",
       p.sampler == emu::SamplerFamily::Llvmpipe ? "fract_then_scale" : "scale_then_floor"},
      {"sampling.float.denormals", p.flushDenormals ? "flushed" : "kept"},
      {"store.unorm8_rounding", "half_even"},
      {"store.unorm16_rounding", p.unorm16Store == emu::UnormRounding::HalfEven ? "half_even" : "half_up"},
      {"framebuffer.between_passes",
       p.framebuffer == emu::FramebufferModel::QuantizePerPass ? "requantized" : "float_tile_cache"},
      {"blend.rgba8_src_alpha", p.framebuffer == emu::FramebufferModel::QuantizePerPass ? "mulnorm" : "float"},
  };
}

TEST(DriverFingerprint, RecoversEveryKnownProfilesParametersFromItsEmulatedFrames) {
  for (const emu::PrecisionProfile& p : emu::knownProfiles()) {
    const DriverFingerprint fp = inferFingerprint(design(), emu::emulateProbeFrames(design(), p));
    const auto expected = expectedValues(p);
    ASSERT_EQ(fp.properties.size(), expected.size()) << p.name;
    for (const auto& [id, value] : expected)
      EXPECT_EQ(valueOf(fp, id), value) << p.name << " " << id << ": " << fp.find(id)->evidence;
    for (const InferredProperty& prop : fp.properties) EXPECT_FALSE(prop.evidence.empty()) << prop.id;
  }
}

TEST(DriverFingerprint, EveryKnownProfileMatchesItselfAlone) {
  for (const emu::PrecisionProfile& p : emu::knownProfiles()) {
    const auto frames = emu::emulateProbeFrames(design(), p);
    const auto comparisons = compareWithKnownProfiles(design(), inferFingerprint(design(), frames), frames);
    for (const ProfileComparison& c : comparisons) {
      EXPECT_EQ(c.matches(), c.profile == &p) << p.name << " against " << c.profile->name;
      EXPECT_EQ(c.framesIdentical, c.profile == &p) << p.name << " against " << c.profile->name;
    }
    EXPECT_EQ(verdictLine(comparisons).rfind("profile: " + std::string(p.name) + " (every property", 0), 0u)
        << verdictLine(comparisons);
  }
}

TEST(DriverFingerprint, EvidenceNamesTheCounts) {
  const DriverFingerprint fp =
      inferFingerprint(design(), emu::emulateProbeFrames(design(), *emu::findProfile("llvmpipe")));
  EXPECT_NE(fp.find("sampling.unorm8.subtexel_bits")->evidence.find("changes 256 times"), std::string::npos);
  EXPECT_NE(fp.find("sampling.float.repeat_scaling")->evidence.find("multiples of 2^-21"), std::string::npos);
}

// A driver voxref has no profile for: llvmpipe's sampler with softpipe's framebuffer.
TEST(DriverFingerprint, AnUnknownCombinationMatchesNoProfileAndSaysWhy) {
  emu::PrecisionProfile hybrid = *emu::findProfile("llvmpipe");
  hybrid.framebuffer = emu::FramebufferModel::FloatTileCache;
  hybrid.maxModelledTargetWidth = 320;
  hybrid.maxModelledTargetHeight = 640;
  const auto frames = emu::emulateProbeFrames(design(), hybrid);
  const DriverFingerprint fp = inferFingerprint(design(), frames);
  const auto comparisons = compareWithKnownProfiles(design(), fp, frames);
  for (const ProfileComparison& c : comparisons) EXPECT_FALSE(c.matches()) << c.profile->name;
  const std::string verdict = verdictLine(comparisons);
  EXPECT_EQ(verdict.rfind("no known profile matches: closest llvmpipe differs in ", 0), 0u) << verdict;
  EXPECT_NE(verdict.find("framebuffer.between_passes: measured float_tile_cache, profile requantized"),
            std::string::npos)
      << verdict;
}

// The unorm8 sweep of a fixed-point sampler without SSSE3 (docs/precision.md: the driver then
// truncates), with coordinates floored to 8 bits: a hand model, so the floor candidates are
// exercised by bits no emulated profile produces.
TEST(DriverFingerprint, RecognisesFlooredCoordinatesAndTruncatingLerps) {
  auto frames = emu::emulateProbeFrames(design(), *emu::findProfile("llvmpipe"));
  const ref::ProbeSweep& sweep = design().sweeps[0];
  ASSERT_EQ(sweep.id, "sweep.rgba8");
  ref::ProbeFrame& f = frames[0];
  for (std::size_t k = 0; k < f.codes.size(); ++k) {
    const int s = static_cast<int>(std::floor(sweep.u(static_cast<int>(k)) * 512.0f)) - 128;
    const int i0 = std::min(s >> 8, 1), w = i0 == 1 ? 0 : s & 255;
    for (int c = 0; c < 4; ++c) {
      const int a = static_cast<int>(sweep.texelCodes[i0][c]), b = static_cast<int>(sweep.texelCodes[1][c]);
      f.codes[k][c] =
          std::bit_cast<std::uint32_t>(emu::unormToFloat(static_cast<std::uint32_t>(a + ((w * (b - a)) >> 8)), 8));
    }
  }
  const DriverFingerprint fp = inferFingerprint(design(), frames);
  EXPECT_EQ(valueOf(fp, "sampling.unorm8.subtexel_bits"), "8");
  EXPECT_EQ(valueOf(fp, "sampling.unorm8.coordinate_rounding"), "floor")
      << fp.find("sampling.unorm8.coordinate_rounding")->evidence;
  EXPECT_EQ(valueOf(fp, "sampling.unorm8.lerp_rounding"), "floor")
      << fp.find("sampling.unorm8.lerp_rounding")->evidence;
}

TEST(DriverFingerprint, GarbageBitsGiveUnknownValuesNotACrash) {
  auto frames = emu::emulateProbeFrames(design(), *emu::findProfile("softpipe"));
  for (ref::ProbeFrame& f : frames)
    for (auto& px : f.codes) px = {0x7fc00000u, 0xffffffffu, 0x00000001u, 0x80000000u};
  const DriverFingerprint fp = inferFingerprint(design(), frames);
  EXPECT_EQ(valueOf(fp, "sampling.unorm8.subtexel_bits"), "unknown");
  EXPECT_EQ(valueOf(fp, "sampling.float.lerp"), "unknown");
  EXPECT_EQ(valueOf(fp, "sampling.float.repeat_scaling"), "unknown");
  EXPECT_EQ(valueOf(fp, "framebuffer.between_passes"), "unknown");
  const auto comparisons = compareWithKnownProfiles(design(), fp, frames);
  EXPECT_EQ(verdictLine(comparisons).rfind("no known profile matches", 0), 0u);
}

TEST(DriverFingerprint, RejectsFramesThatAreNotTheDesigns) {
  auto frames = emu::emulateProbeFrames(design(), *emu::findProfile("llvmpipe"));
  auto missing = frames;
  missing.pop_back();
  EXPECT_THROW(inferFingerprint(design(), missing), std::invalid_argument);
  frames[0].codes.pop_back();
  EXPECT_THROW(inferFingerprint(design(), frames), std::invalid_argument);
}

TEST(ProbeJson, ListsPropertiesProfilesAndTheMatch) {
  const auto frames = emu::emulateProbeFrames(design(), *emu::findProfile("softpipe"));
  const DriverFingerprint fp = inferFingerprint(design(), frames);
  const nlohmann::json j = probeJson(fp, compareWithKnownProfiles(design(), fp, frames));
  EXPECT_EQ(j["properties"].size(), fp.properties.size());
  EXPECT_EQ(j["profiles"].size(), emu::knownProfiles().size());
  EXPECT_EQ(j["matched"], nlohmann::json::array({"softpipe"}));
}

}  // namespace
}  // namespace voxref::conf
