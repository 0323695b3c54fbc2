// `voxref probe`: render the probe frames, infer the driver's fingerprint from their bits alone,
// hold it against the known profiles (docs/probe.md). GL_RENDERER is printed, never consulted.
#include <iostream>
#include <memory>

#include "conformance/cli/commands.h"
#include "conformance/framework/driver_info.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/probe/driver_fingerprint.h"
#include "conformance/framework/probe/fingerprint_match.h"
#include "conformance/framework/probe/probed_profile.h"
#include "conformance/io/atomic_file.h"
#include "gpu/gl_error.h"
#include "gpu/probe_gl.h"

namespace voxref::cli {
namespace {

// Driver fingerprinting (docs/probe.md): 0 a known profile matches the inferred fingerprint, 1 none
// does, 2 usage or no GL context.
struct ProbeOptions {
  std::string driver = "llvmpipe";
  std::filesystem::path out;  // optional JSON report, written atomically
};

int runProbe(const ProbeOptions& o) {
  const auto driver = gpu::parseDriver(o.driver);
  if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "' (llvmpipe, softpipe or egl)");
  std::unique_ptr<gpu::Context> context;
  try {
    context = gpu::createContext(*driver);
  } catch (const gpu::GlUnavailable& e) {
    std::cerr << "voxref: no GL context for --driver " << o.driver << ": " << e.what() << "\n";
    return 2;
  }
  const gpu::ContextInfo& info = context->info();
  const ref::ProbeDesign& design = ref::probeDesign();
  const std::vector<ref::ProbeFrame> frames = gpu::renderProbeFramesGl(*context, design);
  const conf::DriverFingerprint fingerprint = conf::inferFingerprint(design, frames);
  const std::vector<conf::ProfileComparison> comparisons = conf::compareWithKnownProfiles(design, fingerprint, frames);

  std::cout << "voxref probe: " << info.renderer << ", " << info.version << " (" << info.api << "); " << frames.size()
            << " probe frames; environment:";
  for (const auto& [k, v] : gpu::environmentPins()) std::cout << " " << k << "=" << v;
  std::cout << "\n";
  conf::printProbeReport(std::cout, fingerprint, comparisons);
  bool matched = false, confirmsAuto = false;
  std::string how;
  const emu::PrecisionProfile* autoPick = conf::chooseProfile("auto", info, how);
  for (const conf::ProfileComparison& c : comparisons) {
    matched = matched || c.matches();
    confirmsAuto = confirmsAuto || (c.matches() && c.profile == autoPick);
  }
  // A cross-check only: `auto` reads GL_RENDERER and the environment, the probe read nothing but bits.
  std::cout << "auto would pick " << (autoPick ? std::string(autoPick->name) : "no profile") << " (" << how << "), "
            << (confirmsAuto ? "which the probe confirms" : "which the probe does not confirm") << "\n";

  // The profile built from the probed properties: what `conform --profile driver.json` pins.
  const conf::ProbedProfile probed = conf::confirmedProbedProfile(design, frames, fingerprint, "probed", info.renderer);
  if (probed.profile)
    std::cout << "probed profile: built from the " << fingerprint.properties.size()
              << " properties; its emulation reproduces all " << frames.size() << " probe frames"
              << (o.out.empty() ? " (--out FILE.json saves it for voxref conform --profile FILE.json)\n" : "\n");
  else
    std::cout << "no probed profile: " << probed.problem << "\n";

  if (!o.out.empty()) {
    nlohmann::json j = conf::probeJson(fingerprint, comparisons);
    j["driver"] = conf::driverJson(info, autoPick, how);
    j["auto_confirmed"] = confirmsAuto;
    if (probed.profile) {
      j["probed_profile"] = conf::profileToJson(*probed.profile);
      j["assumed"] = probed.assumed;
    } else {
      j["probed_profile_problem"] = probed.problem;
    }
    io::writeFileAtomically(o.out, j.dump(2) + "\n");
    std::cout << "wrote " << o.out.string()
              << (probed.profile
                      ? " (voxref conform --profile " + o.out.string() + " judges exactly against its probed profile)"
                      : std::string())
              << "\n";
  }
  return matched ? 0 : 1;
}

}  // namespace

Subcommand addProbeCommand(CLI::App& app) {
  auto o = std::make_shared<ProbeOptions>();
  CLI::App* sub =
      app.add_subcommand("probe", "infer the driver's precision from probe frames and match it to the known profiles");
  sub->add_option("--driver", o->driver, "llvmpipe, softpipe or egl")->default_val("llvmpipe");
  sub->add_option(
      "--out", o->out,
      "also write the fingerprint and the probed profile as JSON (a driver file for conform --profile FILE.json)");

  return {sub, [o] { return runProbe(*o); }};
}

}  // namespace voxref::cli
