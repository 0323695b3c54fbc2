// How a run's precision profile is chosen (docs/profiles.md, "How a run's profile is chosen"):
// by name, from a driver.json that `voxref probe --out` saved, or, with `auto`, by GL_RENDERER and
// the environment and, where they name no profile, by the probe itself.
//
//   auto         the probe runs (in the run's identity process, about a second on llvmpipe). The
//                profile GL_RENDERER and the environment name (emu::autoProfile) where the probe
//                confirms it (every property, every probe frame bit for bit); else the first known
//                profile whose emulation reproduces every probe frame; else a profile built from
//                the probed properties (probed_profile.h) when its emulation reproduces every probe
//                frame; else none (the envelope alone), with the reason.
//   probed       a profile built from the probed properties even where a known profile matches
//                (how a calibrated profile is held against what the probe alone would build).
//   envelope     none: the spec model alone.
//   measured-envelope  none, but the probe runs and the envelope relies on the arithmetic it
//                measured (emu::MeasuredArithmetic: float filtering, 8-bit store rounding). Opt-in:
//                it assumes unorm16 textures filter as the probe's RGBA32F texture does.
//   NAME         a known profile (emu::knownProfiles()).
//   FILE.json    the probed profile a driver.json holds, after the probe confirms that the driver
//                still probes the same: every saved property equal, every probe frame reproduced.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "emulation/measured_arithmetic.h"
#include "emulation/profile.h"
#include "gpu/context.h"

namespace voxref::conf {

struct ProfileChoice {
  const emu::PrecisionProfile* profile = nullptr;  // nullptr: judged by the envelope alone
  std::string how;                                 // who chose it, on what evidence, in one sentence
  nlohmann::json probe;                            // the probe's report where it ran (probeJson), else null
};

// Needs the run's context (the probe renders on it). Throws UsageError for an unknown name, a
// driver.json that cannot be read or is not one, and a driver that no longer probes as its
// driver.json says ("... no longer probes as driver.json: sampling.float.lerp: probed fused, now
// unfused"): exit status 2.
ProfileChoice chooseRunProfile(const std::string& choice, gpu::Context& gl);

// The arithmetic the envelope may rely on in a run whose probe report is `probe` (ProfileChoice::
// probe): what it measured where the report says so ("envelope_from_measurements"), else the
// spec's rules (no profile choice relies on both a profile and measurements).
emu::MeasuredArithmetic envelopeArithmetic(const nlohmann::json& probe);

}  // namespace voxref::conf
