// voxref check-shader: one case with the user's fragment shader in place of the built-in stage,
// judged by the case's own oracles (docs/shader-interface.md).
#include <cstdio>
#include <iostream>
#include <memory>

#include "conformance/cli/commands.h"
#include "conformance/framework/case_context.h"
#include "conformance/framework/driver_info.h"
#include "conformance/framework/probe/profile_choice.h"
#include "conformance/framework/report/report_files.h"
#include "conformance/framework/runner.h"
#include "conformance/io/atomic_file.h"
#include "conformance/modules/catalog.h"
#include "conformance/modules/sparsegrid/sparsegrid_scene.h"
#include "conformance/modules/timevarying/timevarying_scene.h"
#include "gpu/gl_error.h"
#include "gpu/shader_override.h"

namespace voxref::cli {
namespace {

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

namespace {

const conf::Case& findCase(const std::vector<conf::Case>& cases, const std::string& id) {
  for (const conf::Case& c : cases)
    if (c.id == id) return c;
  throw conf::UsageError("unknown case '" + id + "' (voxref list shows the cases)");
}

// The stage the case runs on GL, from its scene as `voxref render` reads it.
const gpu::ShaderStage& stageOf(const conf::Case& c) {
  const std::string none = "case " + c.id + " has no shader stage a user can replace";
  if (!c.scene)
    throw conf::UsageError(none + " (it renders no single scene; docs/shader-interface.md lists the stages)");
  if (c.scene->value("system", "sparsegrid") == "timevarying")
    return gpu::decoderStage(conf::parseTimeVaryingScene(*c.scene).decoder);
  const conf::SparseGridScene scene = conf::parseSparseGridScene(*c.scene);
  if (!ref::existsInGl(scene.framebuffer))
    throw conf::UsageError(none + " (GL has no " + std::string(ref::name(scene.framebuffer)) +
                           " colour buffer: emulated only)");
  return gpu::combinationStage();
}

int printInterface(const conf::Case& c, const gpu::ShaderStage& stage) {
  std::cout << "case " << c.id << " runs stage `" << stage.name << "` (built-in gpu/shaders/" << stage.fragmentFile
            << ")\n\n"
            << gpu::commonInterface() << "\n\n"
            << gpu::stageInterface(stage) << "\n\n// ---- built-in " << stage.fragmentFile
            << ", a starting point ----\n"
            << stage.fragmentSource;
  return 0;
}

void printResult(const conf::CaseResult& r, const gpu::ShaderOverride& shader) {
  std::cout << "case " << r.id << " with " << shader.fileName << " as `" << shader.stage << "`\n";
  for (const conf::OracleResult& o : r.oracles)
    std::cout << "  " << o.oracle << std::string(o.oracle.size() < 9 ? 9 - o.oracle.size() : 1, ' ')
              << conf::name(o.verdict) << "  " << o.summary << "\n";
  std::cout << "status: " << conf::name(r.status) << (r.message.empty() ? "" : ": " + r.message) << "\n";
}

// A GLSL shader is UTF-8 text (GLSL 4.50, section 3.1); a NUL byte would silently end the source
// GL compiles, and other bytes draw errors from the driver that name no position (Mesa: "lacks
// main"). Throws UsageError naming the file, the byte's offset, line and column.
void checkShaderText(const std::string& source, const std::filesystem::path& file) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < source.size();) {
    const auto c = static_cast<unsigned char>(source[i]);
    std::size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    for (std::size_t k = 1; k < length; ++k)
      if (i + k >= source.size() || (static_cast<unsigned char>(source[i + k]) & 0xc0) != 0x80) length = 0;
    if (c == 0 || length == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", c);
      throw conf::UsageError(file.string() + ": byte " + std::to_string(i) + " (line " + std::to_string(line) +
                             ", column " + std::to_string(column) + "): " + hex + (c == 0 ? " (NUL)" : "") +
                             " is not UTF-8 text; a GLSL shader is UTF-8 text without NUL bytes");
    }
    if (c == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
    i += length;
  }
}

void writeReport(const CheckShaderOptions& o, const conf::RunInfo& run, const std::vector<conf::CaseResult>& results) {
  conf::writeReportFiles(o.out, run, results);
  std::cout << "report: " << (o.out / "index.html").string() << " (results.json, junit.xml beside it)\n";
}

}  // namespace

int runCheckShader(const CheckShaderOptions& o) {
  const std::vector<conf::Case> cases = conf::allCases();
  const conf::Case& c = findCase(cases, o.caseId);
  const gpu::ShaderStage& stage = stageOf(c);
  if (o.printInterface) return printInterface(c, stage);
  if (o.shader.empty()) throw conf::UsageError("--shader FILE.frag is required (or --print-interface)");
  const gpu::ShaderOverride shader{std::string(stage.name), io::readWholeFile(o.shader), o.shader.string()};
  checkShaderText(shader.source, o.shader);

  const auto driver = gpu::parseDriver(o.driver);
  if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "' (llvmpipe, softpipe or egl)");
  std::unique_ptr<gpu::Context> gl;
  try {
    gl = gpu::createContext(*driver);
  } catch (const gpu::GlUnavailable& e) {
    std::cerr << "voxref: no GL context for --driver " << o.driver << ": " << e.what() << "\n";
    return 2;
  }
  // As conform chooses it (auto confirms by the probe; probed; FILE.json): one rule for both.
  const conf::ProfileChoice choice = conf::chooseRunProfile(o.profile, *gl);
  const emu::PrecisionProfile* profile = choice.profile;
  const std::string& how = choice.how;

  std::cout << "voxref check-shader: " << c.id << " on " << gl->info().renderer << " (" << gl->info().version
            << "), profile " << (profile ? std::string(profile->name) : std::string("none: envelope oracle alone"))
            << std::endl;

  // Compile and link first, so that errors are the user's, with the file's line numbers.
  try {
    (void)gpu::buildStageProgram(*gl, stage, &shader);
  } catch (const gpu::ShaderError& e) {
    std::cerr << "voxref: " << shader.fileName << " does not build as stage `" << stage.name
              << "` (line numbers are the file's):\n"
              << e.infoLog()
              << "(voxref prepends #version, PRECISE and sample_point.glsl: docs/shader-interface.md, or voxref "
                 "check-shader --case "
              << c.id << " --print-interface)\n";
    return 2;
  }
  shader.programsBuilt = 0;

  io::ensureDirectory(o.out);
  conf::CaseContext ctx(gl.get(), profile, o.out, o.threads, true, conf::envelopeArithmetic(choice.probe));
  ctx.setShaderOverride(&shader);
  conf::RunInfo run;
  run.command = o.command;
  run.started = conf::utcTimestamp();
  run.driver = conf::driverJson(gl->info(), profile, how);
  conf::CaseResult r = conf::runCase(c, ctx);
  r.description += " [user shader " + shader.fileName + " as " + shader.stage + "]";
  r.figures["user_shader"] = {
      {"file", shader.fileName}, {"stage", shader.stage}, {"programs_built", shader.programsBuilt}};
  printResult(r, shader);
  run.finished = conf::utcTimestamp();
  run.execution = {{"isolation", "none: the case ran in this process"}, {"jobs", 1}};
  writeReport(o, run, {r});
  if (r.status == conf::Status::Skip) {
    std::cerr << "voxref: the shader was not judged: GL skipped the case (" << r.message << ")\n";
    return 2;
  }
  if (shader.programsBuilt == 0 && r.status != conf::Status::Crash) {
    std::cerr << "voxref: the shader was not judged: case " << c.id << " never built stage `" << stage.name << "`\n";
    return 2;
  }
  return r.status == conf::Status::Pass || r.status == conf::Status::Warn ? 0 : 1;
}

}  // namespace

Subcommand addCheckShaderCommand(CLI::App& app, const std::string& invocation) {
  auto o = std::make_shared<CheckShaderOptions>();
  o->command = invocation;
  CLI::App* sub =
      app.add_subcommand("check-shader", "run one case with your fragment shader in place of the built-in stage");
  sub->add_option("--case", o->caseId, "case id from voxref list")->required();
  sub->add_option("--shader", o->shader, "your GLSL fragment shader, without #version (docs/shader-interface.md)");
  sub->add_flag("--print-interface", o->printInterface,
                "print the case's stage: its interface and the built-in shader");
  sub->add_option("--driver", o->driver, "llvmpipe, softpipe or egl")->default_val("llvmpipe");
  sub->add_option("--profile", o->profile,
                  "auto, probed, envelope, measured-envelope, a profile name or a driver file FILE.json (as conform)")
      ->default_val("auto");
  sub->add_option("--out", o->out, "report directory (results.json, junit.xml, index.html)")
      ->default_val("voxref-check-shader");
  sub->add_option("--threads", o->threads, "CPU threads for emulation and reference (0: all)")->default_val(0);

  return {sub, [o] { return runCheckShader(*o); }};
}

}  // namespace voxref::cli
