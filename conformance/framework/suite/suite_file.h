// A suite file (TOML): several `voxref conform` configurations run as one job, as deqp-runner's
// `suite` runs its [[deqp]] entries (docs/ci.md, "Suite files"). One [[conform]] table per
// configuration:
//
//   [[conform]]
//   name = "softpipe"                 # required: the entry's folder under --out, [a-z0-9_-]+, unique
//   driver = "softpipe"               # llvmpipe (default), softpipe or egl
//   profile = "auto"                  # as conform --profile
//   filter = "sparsegrid.hard.*"      # as conform --filter (default "*")
//   caselists = ["lists/hard.txt"]    # files, relative to the suite file's folder
//   fails = ["softpipe-fails.txt"]
//   flakes = []
//   skips = []
//   prefix = "softpipe."              # default: name + "."
//   fraction = 1
//   flake_reruns = 1
//   renderer_check = "^softpipe"
//   version_check = ""
//   [conform.env]                     # set for this configuration's run only
//   GALLIUM_DRIVER = "softpipe"
//
// readSuiteFile throws SuiteFileError naming the file, the line and what was expected there (a
// TOML syntax error, an unknown key, a value of the wrong type, a missing or repeated name).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace voxref::conf {

class SuiteFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SuiteEntry {
  std::string name;
  std::string driver = "llvmpipe", profile = "auto", filter = "*";
  std::vector<std::filesystem::path> caseLists, fails, flakes, skips;  // resolved against the suite's folder
  std::string prefix;                                                  // default: name + "."
  int fraction = 1;
  int flakeReruns = 1;
  std::string rendererCheck, versionCheck;
  std::vector<std::pair<std::string, std::string>> env;  // in the file's order
  int line = 0;                                          // of its [[conform]] header
};

// The entries of the suite file's text; `file` names it in errors and its folder resolves paths.
std::vector<SuiteEntry> parseSuiteText(const std::string& text, const std::filesystem::path& file);
std::vector<SuiteEntry> readSuiteFile(const std::filesystem::path& file);

}  // namespace voxref::conf
