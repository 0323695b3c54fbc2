// The subcommands of the voxref command line (DESIGN.md, "Command line"). Each returns the
// process exit status: 0 success, 1 a conformance failure, 2 bad usage or bad input.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace voxref::cli {

struct ListOptions {
  std::string filter = "*";
  std::string shard;  // "I/N" or empty
  bool runnerControls = false;
};
int runList(const ListOptions& o);

struct ConformOptions {
  std::string filter = "*";
  std::string driver = "llvmpipe";
  std::string profile = "auto";
  std::filesystem::path out = "voxref-report";
  int threads = 0;
  bool allImages = false;
  std::string command;
  int jobs = 1;
  std::string shard;  // "I/N" or empty
  double timeout = 300.0;
  std::filesystem::path baseline;
  bool inProcess = false;
  bool runnerControls = false;
};
int runConform(const ConformOptions& o);

struct RenderOptions {
  std::string scene;  // a scene JSON file or a case id
  std::string backend = "reference";
  std::string driver = "llvmpipe";
  std::string profile = "llvmpipe";  // for the emulation backend ("auto": from --driver's context)
  std::filesystem::path out;
  int threads = 0;
};
int runRender(const RenderOptions& o);

struct BenchOptions {
  std::string filter = "*";
  std::filesystem::path out;
  std::string driver = "llvmpipe";
  bool quick = false;
  int threads = 0;
  std::filesystem::path volumes;
};
int runBench(const BenchOptions& o);

struct EncodeOptions {
  std::string codec;
  std::vector<std::filesystem::path> inputs;  // one raw volume per time step
  std::vector<int> dims;
  std::string type = "uint8";
  bool plume = false;  // the synthetic discharge plume instead of files
  double sparseness = 0.0;
  int plumeSide = 128, plumeSteps = 36;
  std::string transfer = "plume";
  std::string level = "auto";
  std::string encoding = "normalized_rgba8";
  std::string alphaOne = "refine";
  int pageBits = 12;         // leb: 2^pageBits points per page
  bool noGradients = false;  // leb: data channel only
  std::filesystem::path boundsOut;  // leb: also write the per-diamond bounds (reference/iso/BOUNDS_FORMAT.md)
  std::filesystem::path out;
};
int runEncode(const EncodeOptions& o);

struct DecodeOptions {
  std::string codec;
  std::filesystem::path input, out;
  std::optional<int> step;  // timevarying; none: every step
  std::filesystem::path gradientsOut;  // leb
};
int runDecode(const DecodeOptions& o);

struct InfoOptions {
  std::string codec;
  std::filesystem::path input;
};
int runInfo(const InfoOptions& o);

struct FixturesOptions {
  bool generate = false;  // else verify
  std::filesystem::path dir;
  std::string scene = "all";  // a built-in scene name, or all
  std::optional<int> frames;  // none: the scene's own orbit length
  std::filesystem::path volume;  // the user's volume instead of a built-in scene
  std::vector<int> dims;
  std::string type = "uint8";
  std::optional<double> isovalue;  // finite (checked when parsed)
  int threads = 0;
};
int runFixtures(const FixturesOptions& o);

// One case with the user's fragment shader in place of its built-in stage
// (docs/shader-interface.md): 0 pass, 1 fail, 2 usage, missing file, no such stage, or the shader
// does not compile (the info log with the file's line numbers on stderr).
struct CheckShaderOptions {
  std::string caseId;
  std::filesystem::path shader;
  bool printInterface = false;  // print the stage's interface and built-in shader instead
  std::string driver = "llvmpipe";
  std::string profile = "auto";
  std::filesystem::path out = "voxref-check-shader";
  int threads = 0;
  std::string command;
};
int runCheckShader(const CheckShaderOptions& o);

// Driver fingerprinting (docs/probe.md): 0 a known profile matches the inferred fingerprint, 1 none
// does, 2 usage or no GL context.
struct ProbeOptions {
  std::string driver = "llvmpipe";
  std::filesystem::path out;  // optional JSON report, written atomically
};
int runProbe(const ProbeOptions& o);

}  // namespace voxref::cli
