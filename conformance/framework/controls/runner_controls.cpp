#include "conformance/framework/controls/runner_controls.h"

#include <GL/glcorearb.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "conformance/framework/case_context.h"

namespace voxref::conf {
namespace {

void say(const char* what) {
  std::fprintf(stderr, "runner control: %s\n", what);
  std::fflush(stderr);
}

Case control(const char* name, const char* description, std::function<CaseResult(CaseContext&)> run) {
  return Case{std::string("runner.control.") + name, "runner", description, std::move(run), std::nullopt};
}

}  // namespace

std::vector<Case> runnerControlCases() {
  std::vector<Case> cases;
  cases.push_back(control("driver_crash",
                          "expect crash: glTexImage3D reads texels from an unmapped client pointer inside the driver",
                          [](CaseContext& ctx) -> CaseResult {
                            say("handing the driver an unmapped pointer");
                            const gpu::GlApi& gl = ctx.gl()->gl();
                            GLuint texture = 0;
                            gl.GenTextures(1, &texture);
                            gl.BindTexture(GL_TEXTURE_3D, texture);
                            gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
                            // Address 16 is never mapped (mmap_min_addr); the driver copies 256 KiB from it.
                            gl.TexImage3D(GL_TEXTURE_3D, 0, GL_R8, 64, 64, 64, 0, GL_RED, GL_UNSIGNED_BYTE,
                                          reinterpret_cast<const void*>(std::uintptr_t{16}));
                            gl.Finish();
                            throw std::logic_error("the driver read from an unmapped address and did not crash");
                          }));
  cases.push_back(control("segfault", "expect crash: SIGSEGV raised in the case", [](CaseContext&) -> CaseResult {
    say("raising SIGSEGV");
    std::raise(SIGSEGV);
    throw std::logic_error("SIGSEGV did not end the process");
  }));
  cases.push_back(
      control("abort", "expect crash: abort() as a failed assertion in a driver would", [](CaseContext&) -> CaseResult {
        say("calling abort()");
        std::abort();
      }));
  cases.push_back(
      control("exit", "expect crash: the process exits with status 7 without a result", [](CaseContext&) -> CaseResult {
        say("calling exit(7)");
        std::exit(7);
      }));
  cases.push_back(control("hang", "expect timeout: the case sleeps forever", [](CaseContext&) -> CaseResult {
    say("sleeping forever");
    for (;;) pause();
  }));
  cases.push_back(
      control("exception", "expect crash: the case throws std::runtime_error", [](CaseContext&) -> CaseResult {
        say("throwing");
        throw std::runtime_error("a deliberate exception");
      }));
  cases.push_back(control("flaky", "expect flake: fails on its first run in a run, passes when the runner reruns it",
                          [](CaseContext& ctx) -> CaseResult {
                            // The run's parent process (the runner) names the marker: one per run, whatever else
                            // shares the report directory. The case's own process is new at every run of it.
                            const std::filesystem::path marker =
                                ctx.outDir() /
                                (".runner-control-flaky." + std::to_string(static_cast<long>(getppid())));
                            CaseResult r;
                            std::error_code ec;
                            if (std::filesystem::exists(marker, ec)) {
                              std::filesystem::remove(marker, ec);
                              say("second run: passing");
                              r.status = Status::Pass;
                              return r;
                            }
                            std::FILE* f = std::fopen(marker.c_str(), "w");
                            if (f) std::fclose(f);
                            say("first run: failing");
                            r.status = Status::Fail;
                            r.message = "a deliberate failure on the case's first run in this run";
                            return r;
                          }));
  return cases;
}

}  // namespace voxref::conf
