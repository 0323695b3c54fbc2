#include <iostream>
#include <memory>

#include "conformance/bench/bench.h"
#include "conformance/cli/commands.h"
#include "conformance/framework/exit_status.h"

namespace voxref::cli {
namespace {

struct BenchOptions {
  std::string filter = "*";
  std::filesystem::path out;
  std::string driver = "llvmpipe";
  bool quick = false;
  int threads = 0;
  std::filesystem::path volumes;
};

int runBench(const BenchOptions& o) {
  const auto driver = gpu::parseDriver(o.driver);
  if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "'");
  conf::BenchOptions b{o.filter, o.out, *driver, o.quick, o.threads, o.volumes};
  return conf::runBenchmarks(b, std::cout);
}

}  // namespace

Subcommand addBenchCommand(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* sub = app.add_subcommand("bench", "accuracy-versus-time tables of the systems (markdown and JSON)");
  sub->add_option("--filter", o->filter, "shell-style glob on benchmark ids")->default_val("*");
  sub->add_option("--out", o->out, "output directory")->required();
  sub->add_option("--driver", o->driver, "GL driver")->default_val("llvmpipe");
  sub->add_option("--threads", o->threads, "CPU threads for CPU paths (0: all)")->default_val(0);
  sub->add_flag("--quick", o->quick, "small sizes and few levels, for a smoke run");
  sub->add_option("--volumes", o->volumes,
                  "folder of the real volumes (default: ../shared/data/volumes beside the source tree)");

  return {sub, [o] { return runBench(*o); }};
}

}  // namespace voxref::cli
