#include "conformance/framework/probe/fingerprint_match.h"

#include <algorithm>
#include <iomanip>

#include "emulation/probe_emu.h"

namespace voxref::conf {

std::vector<ProfileComparison> compareWithKnownProfiles(const ref::ProbeDesign& design,
                                                        const DriverFingerprint& measured,
                                                        std::span<const ref::ProbeFrame> frames) {
  std::vector<ProfileComparison> out;
  for (const emu::PrecisionProfile& profile : emu::knownProfiles()) {
    const std::vector<ref::ProbeFrame> emulated = emu::emulateProbeFrames(design, profile);
    ProfileComparison c{&profile, inferFingerprint(design, emulated), {}, std::ranges::equal(emulated, frames)};
    for (const InferredProperty& want : c.expected.properties) {
      const InferredProperty* got = measured.find(want.id);
      const std::string value = got ? got->value : "(not measured)";
      if (value != want.value) c.differences.push_back(want.id + ": measured " + value + ", profile " + want.value);
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::string verdictLine(const std::vector<ProfileComparison>& comparisons) {
  std::string matched;
  for (const ProfileComparison& c : comparisons)
    if (c.matches())
      matched +=
          (matched.empty() ? "" : ", ") + std::string(c.profile->name) +
          (c.framesIdentical ? " (every property; probe frames bit-identical to its emulation)"
                             : " (every property; probe frames differ from its emulation in bits no property names)");
  if (!matched.empty()) return "profile: " + matched;
  const auto closest =
      std::ranges::min_element(comparisons, {}, [](const ProfileComparison& c) { return c.differences.size(); });
  if (closest == comparisons.end()) return "no known profile matches: voxref knows no profiles";
  std::string line = "no known profile matches: closest " + std::string(closest->profile->name) + " differs in ";
  for (std::size_t i = 0; i < closest->differences.size(); ++i) line += (i ? "; " : "") + closest->differences[i];
  return line;
}

void printProbeReport(std::ostream& out, const DriverFingerprint& measured,
                      const std::vector<ProfileComparison>& comparisons) {
  std::size_t idWidth = 0, valueWidth = 0;
  for (const InferredProperty& p : measured.properties) {
    idWidth = std::max(idWidth, p.id.size());
    valueWidth = std::max(valueWidth, p.value.size());
  }
  for (const InferredProperty& p : measured.properties)
    out << "  " << std::left << std::setw(static_cast<int>(idWidth)) << p.id << "  "
        << std::setw(static_cast<int>(valueWidth)) << p.value << "  " << p.evidence << "\n";
  for (const ProfileComparison& c : comparisons)
    if (!c.matches())
      out << "  not " << c.profile->name << ": differs in " << c.differences.size() << " of "
          << c.expected.properties.size() << " properties\n";
  out << verdictLine(comparisons) << "\n";
}

nlohmann::json propertiesJson(const DriverFingerprint& measured) {
  nlohmann::json props = nlohmann::json::array();
  for (const InferredProperty& p : measured.properties)
    props.push_back({{"id", p.id}, {"value", p.value}, {"evidence", p.evidence}});
  return props;
}

nlohmann::json probeJson(const DriverFingerprint& measured, const std::vector<ProfileComparison>& comparisons) {
  nlohmann::json props = propertiesJson(measured), profiles = nlohmann::json::array(),
                 matched = nlohmann::json::array();
  for (const ProfileComparison& c : comparisons) {
    profiles.push_back({{"name", c.profile->name},
                        {"matches", c.matches()},
                        {"differences", c.differences},
                        {"frames_identical", c.framesIdentical}});
    if (c.matches()) matched.push_back(c.profile->name);
  }
  return {{"properties", props}, {"profiles", profiles}, {"matched", matched}, {"verdict", verdictLine(comparisons)}};
}

}  // namespace voxref::conf
