// A measured driver fingerprint held against voxref's known precision profiles (emulation/profile.h),
// and its report (`voxref probe`, docs/probe.md).
//
// A profile's expected fingerprint is derived, not tabulated: the inference of driver_fingerprint.h
// applied to the probe frames the profile's emulation gives (emulation/probe_emu.h). A profile
// matches when every property has the same value; the frames are also compared bit for bit, as
// the stronger statement that the profile models every probed bit of the driver.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/framework/probe/driver_fingerprint.h"
#include "emulation/profile.h"

namespace voxref::conf {

struct ProfileComparison {
  const emu::PrecisionProfile* profile = nullptr;
  DriverFingerprint expected;
  std::vector<std::string> differences;  // "sampling.float.lerp: measured unfused, profile fused"
  bool framesIdentical = false;          // every probe frame bit-identical to the profile's emulation
  bool matches() const { return differences.empty(); }
};

// One comparison per known profile, in emu::knownProfiles() order.
std::vector<ProfileComparison> compareWithKnownProfiles(const ref::ProbeDesign& design,
                                                        const DriverFingerprint& measured,
                                                        std::span<const ref::ProbeFrame> frames);

// "profile: llvmpipe (...)" or "no known profile matches: closest X differs in ...": the verdict
// line of the report.
std::string verdictLine(const std::vector<ProfileComparison>& comparisons);

// The fingerprint as a table (property, value, evidence), then the verdict.
void printProbeReport(std::ostream& out, const DriverFingerprint& measured,
                      const std::vector<ProfileComparison>& comparisons);

// [{id, value, evidence}]: the measured properties, as probeJson and the run's report give them.
nlohmann::json propertiesJson(const DriverFingerprint& measured);

// {"properties": [{id, value, evidence}], "profiles": [{name, matches, differences, frames_identical}],
//  "matched": [names]}
nlohmann::json probeJson(const DriverFingerprint& measured, const std::vector<ProfileComparison>& comparisons);

}  // namespace voxref::conf
