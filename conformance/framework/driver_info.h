// The identity of the driver under test, as every report records it (docs/precision.md: renderer
// and version strings, environment pins, CPU flags) and the profile chosen for it.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "emulation/profile.h"
#include "gpu/context.h"

namespace voxref::conf {

struct CpuFlags {
  bool ssse3 = false, sse4_1 = false, avx2 = false, fma = false, f16c = false;
};
CpuFlags detectCpuFlags();

// The profile for `choice` ("auto", "envelope" or a profile name) on this context. nullptr means
// no driver arithmetic to emulate: "envelope" asks for that (the spec model alone, as a driver
// voxref has no profile for is judged), and "auto" gives it for an unknown renderer. `how` says
// what was decided and why.
// Throws std::invalid_argument for an unknown profile name (the message lists the known ones).
const emu::PrecisionProfile* chooseProfile(const std::string& choice, const gpu::ContextInfo& info, std::string& how);

nlohmann::json driverJson(const gpu::ContextInfo& info, const emu::PrecisionProfile* profile, const std::string& how);

}  // namespace voxref::conf
