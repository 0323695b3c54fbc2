// voxref: the command line (docs/design.md, "Command line"). Every subcommand adds itself and its
// options (commands.h); this file only parses and runs the one chosen.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "conformance/cli/commands.h"
#include "conformance/cli/memory_policy.h"
#include "conformance/io/temporary_files.h"

namespace voxref::cli {

CLI::Validator finiteNumber() {
  return CLI::Validator(
      [](std::string& s) {
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(s.c_str(), &end);
        if (end == s.c_str() || *end != '\0') return "expected a number, got '" + s + "'";
        if (!std::isfinite(v) || (errno == ERANGE && std::abs(v) > 1.0))
          return "expected a finite number, got '" + s + "'";
        return std::string();
      },
      "FINITE");
}

}  // namespace voxref::cli

namespace {

std::string joinArgs(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace voxref::cli;
  keepFreedMemoryForReuse();
  voxref::io::removeTemporariesOnSignals();
  CLI::App app{"voxref: validation suite for compressed volume rendering on GPUs"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "voxref 0.1.0");
  const std::string invocation = joinArgs(argc, argv);
  std::vector<Subcommand> subcommands{addListCommand(app), addConformCommand(app, invocation), addRenderCommand(app),
                                      addBenchCommand(app)};
  for (Subcommand& s : addCodecCommands(app)) subcommands.push_back(std::move(s));
  subcommands.push_back(addFixturesCommand(app));
  subcommands.push_back(addCheckShaderCommand(app, invocation));
  subcommands.push_back(addProbeCommand(app));
  subcommands.push_back(addSuiteCommand(app));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    for (const Subcommand& s : subcommands)
      if (s.app->parsed()) return s.run();
  } catch (const std::exception& e) {
    std::cerr << "voxref: " << e.what() << "\n";
    return 2;
  }
  return 2;
}
