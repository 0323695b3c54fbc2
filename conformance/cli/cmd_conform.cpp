#include <cstdlib>
#include <iostream>
#include <memory>

#include "conformance/cli/case_selection.h"
#include "conformance/cli/commands.h"
#include "conformance/framework/runner.h"
#include "gpu/gl_error.h"

namespace voxref::cli {
namespace {

// What the command line sets: most options straight into the run's options; the driver and the
// shard are parsed when the command runs.
struct ConformOptions {
  conf::RunOptions run;
  std::string driver = "llvmpipe";
  std::string shard;  // "I/N" or empty
  bool runnerControls = false;
};

int runConform(ConformOptions o) {
  conf::RunOptions& run = o.run;
  const auto driver = gpu::parseDriver(o.driver);
  if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "' (llvmpipe, softpipe or egl)");
  if (run.inProcess && o.runnerControls)
    throw conf::UsageError("--in-process cannot run the runner's control cases: they end the process");
  if (run.timeLimitSeconds < 0) throw conf::UsageError("--timeout must be 0 (none) or a number of seconds");
  run.driver = *driver;
  run.shard = shardOptionOrCi(o.shard, run.shardFrom);  // GitLab's parallel: N sets the CI variables
  try {
    return conf::runConformance(run, catalogue(o.runnerControls), std::cout).exitCode;
  } catch (const gpu::GlUnavailable& e) {
    std::cerr << "voxref: no GL context for --driver " << o.driver << ": " << e.what() << "\n";
    return 2;
  } catch (const conf::DriverCheckError& e) {
    std::cerr << "voxref: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace

Subcommand addConformCommand(CLI::App& app, const std::string& invocation) {
  auto o = std::make_shared<ConformOptions>();
  o->run.command = invocation;
  CLI::App* sub =
      app.add_subcommand("conform", "run cases on a GL driver against emulation and reference; write a report");
  sub->add_option("--filter", o->run.filter, "shell-style glob on case ids")->default_val("*");
  sub->add_option("--driver", o->driver, "llvmpipe, softpipe or egl")->default_val("llvmpipe");
  sub->add_option("--profile", o->run.profile,
                  "auto (by GL_RENDERER, else the probe), probed, envelope, measured-envelope (the envelope from the "
                  "probe's measured arithmetic), a profile name, or a driver file FILE.json that "
                  "voxref probe --out wrote")
      ->default_val("auto");
  sub->add_option("--out", o->run.outDir, "report directory (results.json, junit.xml, index.html)")
      ->default_val("voxref-report");
  sub->add_option("--threads", o->run.threads, "CPU threads for emulation and reference (0: all)")->default_val(0);
  sub->add_flag("--all-images", o->run.allImages, "write images for every case, not only failing and warned ones");
  sub->add_option("--jobs,-j", o->run.jobs, "case processes at once; results do not depend on it")->default_val(1);
  sub->add_option("--shard", o->shard, "I/N: run only shard I of N of the selection (round robin, catalogue order)");
  sub->add_option("--timeout", o->run.timeLimitSeconds,
                  "seconds a case may take before it is killed and reported as timeout (0: none)")
      ->default_val(300);
  sub->add_option("--baseline", o->run.baseline,
                  "an earlier results.json: report changes; exit 3 when a case regressed");
  sub->add_flag("--in-process", o->run.inProcess,
                "run cases in this process, without isolation or time limit (for a debugger)");
  sub->add_flag("--runner-controls", o->runnerControls,
                "add the runner's control cases (runner.control.*: deliberate driver crash, segfault, abort, exit, "
                "hang, exception)");

  // Running in a CI fleet, as deqp-runner does (docs/ci.md).
  sub->add_option("--caselist", o->run.caseLists,
                  "a file of case ids, one per line: the selection (with --filter); repeatable");
  sub->add_option("--fails", o->run.failsFiles,
                  "expected failures, 'case.id,Status' per line (deqp-runner's fails file); repeatable");
  sub->add_option("--flakes", o->run.flakesFiles, "regular expressions of known flaky cases, one per line; repeatable");
  sub->add_option("--skips", o->run.skipsFiles, "regular expressions of cases not to run, one per line; repeatable");
  sub->add_option("--flake-reruns", o->run.flakeReruns,
                  "reruns of a case that fails unexpectedly; a pass on one is a Flake, not a failure")
      ->default_val(1);
  sub->add_option("--fraction", o->run.fraction, "run every Nth case of the selection (before --shard)")
      ->default_val(1);
  sub->add_option("--renderer-check", o->run.rendererCheck,
                  "regular expression GL_RENDERER must match, or the run stops before any case (exit 2)");
  sub->add_option("--version-check", o->run.versionCheck,
                  "regular expression GL_VERSION must match, or the run stops before any case (exit 2)");
  sub->add_option("--junit-limit", o->run.junit.limit,
                  "list at most N failed cases in junit.xml (failures.csv has all)");
  sub->add_option("--junit-template", o->run.junit.linkTemplate,
                  "text added to each failure in junit.xml, {{testcase}} replaced by the case id (a link)");
  sub->add_option("--prefix", o->run.junit.idPrefix,
                  "put before every case id in the CSV files and junit.xml, and in what the expectation files name");
  sub->add_option("--slowest", o->run.slowest, "list the N slowest cases at the end")->default_val(5);
  return {sub, [o] { return runConform(*o); }};
}

}  // namespace voxref::cli
