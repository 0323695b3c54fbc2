#include "conformance/framework/probe/probed_profile.h"

#include <gtest/gtest.h>

#include "emulation/probe_emu.h"

namespace voxref::conf {
namespace probed_profile_test {

const ref::ProbeDesign& design() { return ref::probeDesign(); }

// The frames a driver modelled by `p` would give, and their fingerprint.
struct Driver {
  std::vector<ref::ProbeFrame> frames;
  DriverFingerprint fingerprint;
};
Driver driverLike(const emu::PrecisionProfile& p) {
  Driver d;
  d.frames = emu::emulateProbeFrames(design(), p);
  d.fingerprint = inferFingerprint(design(), d.frames);
  return d;
}

// Every known profile, probed as a driver would be: the profile built from its fingerprint alone
// reproduces its probe frames bit for bit (the two are built by different code: the hand-made
// profile's fields, and the inference from bits).
TEST(ProbedProfile, EveryKnownProfileIsRebuiltFromItsProbeAlone) {
  for (const emu::PrecisionProfile& known : emu::knownProfiles()) {
    const Driver d = driverLike(known);
    const ProbedProfile built = confirmedProbedProfile(design(), d.frames, d.fingerprint, "probed", "test");
    ASSERT_TRUE(built.profile) << known.name << ": " << built.problem;
    EXPECT_TRUE(built.profile->probed);
    EXPECT_EQ(built.profile->floatLerp, known.floatLerp) << known.name;
    EXPECT_EQ(built.profile->aos8BitSampling, known.aos8BitSampling) << known.name;
    EXPECT_EQ(built.profile->framebuffer, known.framebuffer) << known.name;
    EXPECT_FALSE(built.profile->textureTileCache.aliasing) << "not probed: assumed absent";
    EXPECT_FALSE(built.assumed.empty());
  }
}

// llvmpipe below SSSE3: 8-bit lerps that floor. No known profile has it; the probe builds one.
TEST(ProbedProfile, TheFlooringLerpOfLlvmpipeWithoutSsse3IsBuiltAndHeld) {
  emu::PrecisionProfile floor = *emu::findProfile("llvmpipe-nofma");
  floor.aosLerp = emu::Lerp8Rounding::Floor;
  const Driver d = driverLike(floor);
  EXPECT_EQ(d.fingerprint.find("sampling.unorm8.lerp_rounding")->value, "floor");
  const ProbedProfile built = confirmedProbedProfile(design(), d.frames, d.fingerprint, "probed", "test");
  ASSERT_TRUE(built.profile) << built.problem;
  EXPECT_EQ(built.profile->aosLerp, emu::Lerp8Rounding::Floor);
  EXPECT_EQ(framesNotReproduced(design(), d.frames, *emu::findProfile("llvmpipe-nofma")) > 0, true);
}

TEST(ProbedProfile, AnUnknownPropertyBuildsNoProfileAndSaysWhich) {
  Driver d = driverLike(*emu::findProfile("llvmpipe"));
  for (InferredProperty& p : d.fingerprint.properties)
    if (p.id == "sampling.float.lerp") p.value = "unknown";
  const ProbedProfile built = profileFromFingerprint(d.fingerprint, "probed", "test");
  EXPECT_FALSE(built.profile);
  EXPECT_NE(built.problem.find("sampling.float.lerp is unknown"), std::string::npos) << built.problem;
}

TEST(ProbedProfile, JsonRoundTripKeepsEveryStage) {
  for (const emu::PrecisionProfile& known : emu::knownProfiles()) {
    const emu::PrecisionProfile& back = profileFromJson(profileToJson(known));
    EXPECT_EQ(profileToJson(back), profileToJson(known)) << known.name;
    EXPECT_EQ(framesNotReproduced(design(), emu::emulateProbeFrames(design(), known), back), 0u) << known.name;
  }
  nlohmann::json broken = profileToJson(*emu::findProfile("llvmpipe"));
  broken.erase("float_lerp");
  EXPECT_THROW(profileFromJson(broken), std::invalid_argument);
}

TEST(ProbedProfile, AMovedPropertyIsNamed) {
  const Driver llvmpipe = driverLike(*emu::findProfile("llvmpipe"));
  const Driver nofma = driverLike(*emu::findProfile("llvmpipe-nofma"));
  nlohmann::json saved = nlohmann::json::array();
  for (const InferredProperty& p : llvmpipe.fingerprint.properties) saved.push_back({{"id", p.id}, {"value", p.value}});
  EXPECT_TRUE(movedProperties(saved, llvmpipe.fingerprint).empty());
  const std::vector<std::string> moved = movedProperties(saved, nofma.fingerprint);
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_EQ(moved[0], "sampling.float.lerp: probed fused, now unfused");
}

}  // namespace probed_profile_test
}  // namespace voxref::conf
