#include "conformance/framework/probe/profile_choice.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "conformance/framework/driver_info.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/probe/driver_fingerprint.h"
#include "conformance/framework/probe/fingerprint_match.h"
#include "conformance/framework/probe/probed_profile.h"
#include "emulation/probe_emu.h"
#include "gpu/probe_gl.h"

namespace voxref::conf {
namespace {

struct Probed {
  std::vector<ref::ProbeFrame> frames;
  DriverFingerprint fingerprint;
  std::vector<ProfileComparison> comparisons;
};

// The fingerprint of frames the driver rendered, and every known profile held against it.
Probed judgeFrames(std::vector<ref::ProbeFrame> frames) {
  const ref::ProbeDesign& design = ref::probeDesign();
  Probed p;
  p.frames = std::move(frames);
  p.fingerprint = inferFingerprint(design, p.frames);
  p.comparisons = compareWithKnownProfiles(design, p.fingerprint, p.frames);
  return p;
}

Probed probe(gpu::Context& gl) { return judgeFrames(gpu::renderProbeFramesGl(gl, ref::probeDesign())); }

// Records the probed profile a run is judged against, and what it assumes, in the probe's report.
void recordProbedProfile(ProfileChoice& c, const ProbedProfile& built, const char* chosenBy) {
  c.profile = &keepProfile(*built.profile);
  c.probe["chosen_by"] = chosenBy;
  c.probe["probed_profile"] = profileToJson(*c.profile);
  c.probe["assumed"] = built.assumed;
}

std::string frameCount(const Probed& p) { return std::to_string(p.frames.size()) + " probe frames"; }

// auto: the profile GL_RENDERER and the environment name, where the probe confirms it; else the
// probe decides. `named` is that profile (nullptr: none), `namedHow` why it was named.
ProfileChoice chooseByProbe(gpu::Context& gl, const emu::PrecisionProfile* named, const std::string& namedHow) {
  ProfileChoice c;
  const ref::ProbeDesign& design = ref::probeDesign();
  std::vector<ref::ProbeFrame> frames = gpu::renderProbeFramesGl(gl, design);
  if (named) {  // the common case first: only the named profile's emulation (frames equal: every property equal)
    if (framesNotReproduced(design, frames, *named) == 0) {
      c.profile = named;
      c.how = namedHow + "; the probe confirms it: all " + std::to_string(frames.size()) +
              " probe frames bit-identical to its emulation";
      c.probe = {{"properties", propertiesJson(inferFingerprint(design, frames))},
                 {"confirmed", named->name},
                 {"chosen_by", "name, confirmed by the probe"}};
      return c;
    }
  }
  const Probed p = judgeFrames(std::move(frames));  // rendered once
  c.probe = probeJson(p.fingerprint, p.comparisons);
  const std::string properties = std::to_string(p.fingerprint.properties.size()) + " properties";
  const std::string why =
      named ? "auto: " + std::string(named->name) + " by name (" + namedHow + "), which the probe does not confirm; "
            : "auto: GL_RENDERER '" + gl.info().renderer + "' names no profile; ";
  for (const ProfileComparison& k : p.comparisons)
    if (k.matches() && k.framesIdentical) {
      c.profile = k.profile;
      c.how = why + "the probe chose " + std::string(k.profile->name) + ": all " + frameCount(p) +
              " bit-identical to its emulation, every one of the " + properties + " its value";
      c.probe["chosen_by"] = "probe: known profile";
      return c;
    }
  const ProbedProfile built =
      confirmedProbedProfile(ref::probeDesign(), p.frames, p.fingerprint, "probed", gl.info().renderer);
  if (built.profile) {
    recordProbedProfile(c, built, "probe: probed profile");
    c.how = why + "no known profile reproduces the probe (" + verdictLine(p.comparisons) +
            "); judged against a profile built from the " + std::to_string(p.fingerprint.properties.size()) +
            " probed properties, whose emulation reproduces all " + frameCount(p);
    return c;
  }
  c.how = why + "no known profile reproduces the probe (" + verdictLine(p.comparisons) +
          ") and no profile can be built from it (" + built.problem +
          "); judged by the envelope oracle alone (--profile measured-envelope relies on what the probe measured)";
  c.probe["chosen_by"] = "probe: none";
  return c;
}

nlohmann::json readDriverFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("--profile " + path.string() + ": cannot read the file");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    throw UsageError("--profile " + path.string() + ": not JSON (" + e.what() + ")");
  }
  if (!j.is_object() || !j.contains("properties"))
    throw UsageError("--profile " + path.string() + ": not a driver file of `voxref probe --out` (no properties)");
  if (!j.contains("probed_profile"))
    throw UsageError("--profile " + path.string() +
                     ": holds no probed profile (the probe that wrote it could not build one: " +
                     j.value("probed_profile_problem", std::string("no reason recorded")) + ")");
  return j;
}

// FILE.json: the pin. The driver must still probe as the file says, property for property, and
// the saved profile's emulation must reproduce every probe frame of the driver now.
ProfileChoice chooseFromFile(gpu::Context& gl, const std::filesystem::path& path) {
  const nlohmann::json saved = readDriverFile(path);
  const emu::PrecisionProfile* profile = nullptr;
  try {
    profile = &profileFromJson(saved.at("probed_profile"));
  } catch (const std::invalid_argument& e) {
    throw UsageError("--profile " + path.string() + ": " + e.what());
  }
  const Probed p = probe(gl);
  const std::vector<std::string> moved = movedProperties(saved.at("properties"), p.fingerprint);
  if (!moved.empty()) {
    std::string list;
    for (const std::string& m : moved) list += (list.empty() ? "" : "; ") + m;
    throw UsageError("the driver no longer probes as " + path.string() + ": " + list);
  }
  if (const std::size_t differing = framesNotReproduced(ref::probeDesign(), p.frames, *profile); differing != 0)
    throw UsageError("the driver no longer probes as " + path.string() + ": its profile's emulation differs in " +
                     std::to_string(differing) + " of " + frameCount(p));
  ProfileChoice c;
  c.profile = profile;
  c.how = "named on the command line: the probed profile of " + path.string() +
          "; the probe confirms it (every property as saved, all " + frameCount(p) + " reproduced)";
  c.probe = probeJson(p.fingerprint, p.comparisons);
  c.probe["chosen_by"] = "driver file";
  return c;
}

}  // namespace

emu::MeasuredArithmetic envelopeArithmetic(const nlohmann::json& probe) {
  if (!probe.is_object() || !probe.value("envelope_from_measurements", false)) return {};
  return emu::measuredArithmetic([&](const char* id) {
    for (const auto& p : probe.value("properties", nlohmann::json::array()))
      if (p.value("id", std::string()) == id) return p.value("value", std::string());
    return std::string();
  });
}

ProfileChoice chooseRunProfile(const std::string& choice, gpu::Context& gl) {
  if (choice.size() > 5 && choice.ends_with(".json")) return chooseFromFile(gl, choice);
  if (choice == "measured-envelope") {
    const Probed p = probe(gl);
    ProfileChoice c;
    c.probe = probeJson(p.fingerprint, p.comparisons);
    c.probe["chosen_by"] = "probe: measured envelope (asked for)";
    c.probe["envelope_from_measurements"] = true;
    c.how =
        "named on the command line: measured-envelope: no profile; the envelope relies on what the probe "
        "measured: " +
        envelopeArithmetic(c.probe).describe();
    return c;
  }
  if (choice == "probed") {
    const Probed p = probe(gl);
    const ProbedProfile built =
        confirmedProbedProfile(ref::probeDesign(), p.frames, p.fingerprint, "probed", gl.info().renderer);
    if (!built.profile)
      throw UsageError("--profile probed: the probe cannot build a profile of this driver: " + built.problem);
    ProfileChoice c;
    c.probe = probeJson(p.fingerprint, p.comparisons);
    recordProbedProfile(c, built, "probe: probed profile (asked for)");
    c.how = "named on the command line: probed, a profile built from the " +
            std::to_string(p.fingerprint.properties.size()) +
            " probed properties (whatever GL_RENDERER names), whose emulation reproduces all " + frameCount(p);
    return c;
  }
  ProfileChoice c;
  try {
    c.profile = chooseProfile(choice, gl.info(), c.how);
  } catch (const std::invalid_argument& e) {
    std::string what = e.what();  // "unknown profile 'x' (known: auto, envelope, NAMES)": and the run's own two
    if (const auto at = what.find("known: auto, envelope, "); at != std::string::npos)
      what.insert(at + 23, "measured-envelope, probed, a driver file FILE.json, ");
    throw UsageError(what);
  }
  if (choice == "auto") return chooseByProbe(gl, c.profile, c.how);
  return c;
}

}  // namespace voxref::conf
