// The subcommands of the voxref command line (docs/design.md, "Command line"), one file each
// (cmd_<name>.cpp). Each owns its options: it adds itself, with its options, to the application
// and hands back what runs it once the command line is parsed. A run returns the process exit
// status: 0 success, 1 a conformance failure, 2 bad usage or bad input, 3 a regression against a
// baseline (conformance/framework/exit_status.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace voxref::cli {

// What main() needs of a subcommand: whether it was chosen, and its run.
struct Subcommand {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

// `invocation` is the whole command line, for the reports that record it.
Subcommand addListCommand(CLI::App& app);
Subcommand addConformCommand(CLI::App& app, const std::string& invocation);
Subcommand addRenderCommand(CLI::App& app);
Subcommand addBenchCommand(CLI::App& app);
std::vector<Subcommand> addCodecCommands(CLI::App& app);  // encode, decode and info (cmd_codec.cpp)
Subcommand addFixturesCommand(CLI::App& app);
Subcommand addCheckShaderCommand(CLI::App& app, const std::string& invocation);
Subcommand addProbeCommand(CLI::App& app);
Subcommand addSuiteCommand(CLI::App& app);  // several conform configurations from a suite file (TOML)

// An option value that is a finite number: "nan", "inf" and "1e309" (beyond double) are refused
// when the command line is parsed, with the option's name.
CLI::Validator finiteNumber();

}  // namespace voxref::cli
