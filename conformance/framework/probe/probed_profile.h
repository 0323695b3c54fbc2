// Profiles built from what the probe measured (issue 16), for drivers nobody calibrated by hand:
// each stage of the emulator set to the variant the probe's fingerprint names (fixed-point
// subtexel bits, coordinate and lerp rounding, float lerp fusion, denormals, REPEAT scaling,
// unorm stores, between-pass quantization, blend arithmetic), and, as JSON, what `voxref probe
// --out driver.json` saves and `voxref conform --profile driver.json` pins.
//
// The probe measures the arithmetic, not every behaviour: what it does not measure (texture
// tile-cache aliasing, texelFetch outside the texture, folding x * 0.0, the largest target a tile
// cache model holds) takes the GL semantics and is listed as assumed. Where such an assumption
// is wrong, the exact oracle fails and says that the probed model does not hold.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/framework/probe/driver_fingerprint.h"
#include "emulation/profile.h"

namespace voxref::conf {

struct ProbedProfile {
  std::optional<emu::PrecisionProfile> profile;  // absent when a property has no emulator stage
  std::string problem;                           // why it is absent ("sampling.unorm8.lerp_rounding is unknown")
  std::vector<std::string> assumed;              // what the probe does not measure, and what was taken
};

// The profile named `name` whose stages are the fingerprint's values. Its strings live for the
// process (profiles are views).
ProbedProfile profileFromFingerprint(const DriverFingerprint& fingerprint, const std::string& name,
                                     const std::string& renderer);

// How many of the driver's probe frames the profile's emulation does not reproduce bit for bit.
std::size_t framesNotReproduced(const ref::ProbeDesign& design, std::span<const ref::ProbeFrame> frames,
                                const emu::PrecisionProfile& profile);

// profileFromFingerprint, kept only when its emulation reproduces every probe frame bit for bit
// (else `problem` says how many frames differ): the profile a run may judge exactly against.
ProbedProfile confirmedProbedProfile(const ref::ProbeDesign& design, std::span<const ref::ProbeFrame> frames,
                                     const DriverFingerprint& fingerprint, const std::string& name,
                                     const std::string& renderer);

// The properties of `saved` (a fingerprint as probeJson writes it) that differ from `now`, as
// "sampling.float.lerp: probed fused, now unfused"; empty when the driver probes the same.
std::vector<std::string> movedProperties(const nlohmann::json& saved, const DriverFingerprint& now);

// Every field of a profile (its own or a probed one) and back: how a run hands a probed profile
// to its case processes, and how driver.json stores it. fromJson throws std::invalid_argument
// naming the field; the strings of the profile it returns live for the process.
nlohmann::json profileToJson(const emu::PrecisionProfile& profile);
const emu::PrecisionProfile& profileFromJson(const nlohmann::json& j);

// A copy of `profile` kept for the life of the process (profiles are handed out as pointers).
const emu::PrecisionProfile& keepProfile(const emu::PrecisionProfile& profile);

}  // namespace voxref::conf
