// voxref: the command line. Subcommands: list, conform, render, bench (DESIGN.md).
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "conformance/cli/commands.h"
#include "conformance/modules/iso/iso_scene.h"

namespace {

std::string joinArgs(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

// A number that is finite: "nan", "inf" and "1e309" (beyond double) are refused with the option's name.
const CLI::Validator finiteNumber(
    [](std::string& s) {
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(s.c_str(), &end);
      if (end == s.c_str() || *end != '\0') return "expected a number, got '" + s + "'";
      if (!std::isfinite(v) || (errno == ERANGE && std::abs(v) > 1.0)) return "expected a finite number, got '" + s + "'";
      return std::string();
    },
    "FINITE");

}  // namespace

int main(int argc, char** argv) {
  using namespace voxref::cli;
  CLI::App app{"voxref: validation suite for compressed volume rendering on GPUs"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "voxref 0.1.0");

  ListOptions list;
  auto* listCmd = app.add_subcommand("list", "every case id with one line on what it checks");
  listCmd->add_option("--filter", list.filter, "shell-style glob on case ids")->default_val("*");
  listCmd->add_option("--shard", list.shard, "I/N: only the cases shard I of N runs (as conform --shard)");
  listCmd->add_flag("--runner-controls", list.runnerControls, "also the runner's control cases (deliberate crash, abort, hang)");

  ConformOptions conform;
  auto* conformCmd = app.add_subcommand("conform", "run cases on a GL driver against emulation and reference; write a report");
  conformCmd->add_option("--filter", conform.filter, "shell-style glob on case ids")->default_val("*");
  conformCmd->add_option("--driver", conform.driver, "llvmpipe, softpipe or egl")->default_val("llvmpipe");
  conformCmd->add_option("--profile", conform.profile, "auto or a precision profile name")->default_val("auto");
  conformCmd->add_option("--out", conform.out, "report directory (results.json, junit.xml, index.html)")->default_val("voxref-report");
  conformCmd->add_option("--threads", conform.threads, "CPU threads for emulation and reference (0: all)")->default_val(0);
  conformCmd->add_flag("--all-images", conform.allImages, "write images for every case, not only failing and warned ones");
  conformCmd->add_option("--jobs,-j", conform.jobs, "case processes at once; results do not depend on it")->default_val(1);
  conformCmd->add_option("--shard", conform.shard, "I/N: run only shard I of N of the selection (round robin, catalogue order)");
  conformCmd->add_option("--timeout", conform.timeout, "seconds a case may take before it is killed and reported as timeout (0: none)")
      ->default_val(300);
  conformCmd->add_option("--baseline", conform.baseline, "an earlier results.json: report changes; exit 3 when a case regressed");
  conformCmd->add_flag("--in-process", conform.inProcess, "run cases in this process, without isolation or time limit (for a debugger)");
  conformCmd->add_flag("--runner-controls", conform.runnerControls,
                       "add the runner's control cases (runner.control.*: deliberate driver crash, segfault, abort, exit, hang, exception)");

  RenderOptions render;
  auto* renderCmd = app.add_subcommand("render", "render one scene with one backend into an EXR image");
  renderCmd->add_option("--scene", render.scene, "scene JSON file, or a case id from voxref list")->required();
  renderCmd->add_option("--backend", render.backend, "reference, emulation or gl")->default_val("reference");
  renderCmd->add_option("--driver", render.driver, "GL driver for the gl backend")->default_val("llvmpipe");
  renderCmd->add_option("--profile", render.profile, "precision profile for the emulation backend")->default_val("llvmpipe");
  renderCmd->add_option("--out", render.out, "output image (.exr)")->required();
  renderCmd->add_option("--threads", render.threads, "CPU threads (0: all)")->default_val(0);

  BenchOptions bench;
  auto* benchCmd = app.add_subcommand("bench", "accuracy-versus-time tables of the systems (markdown and JSON)");
  benchCmd->add_option("--filter", bench.filter, "shell-style glob on benchmark ids")->default_val("*");
  benchCmd->add_option("--out", bench.out, "output directory")->required();
  benchCmd->add_option("--driver", bench.driver, "GL driver")->default_val("llvmpipe");
  benchCmd->add_option("--threads", bench.threads, "CPU threads for CPU paths (0: all)")->default_val(0);
  benchCmd->add_flag("--quick", bench.quick, "small sizes and few levels, for a smoke run");
  benchCmd->add_option("--volumes", bench.volumes, "folder of the real volumes (default: ../shared/data/volumes beside the source tree)");

  EncodeOptions encode;
  auto* encodeCmd = app.add_subcommand("encode", "encode volumes with a codec into a file");
  encodeCmd->add_option("--codec", encode.codec, "timevarying or leb")->required();
  encodeCmd->add_option("--input", encode.inputs, "raw volume files (.raw or .raw.gz): timevarying one per time step, leb one");
  encodeCmd->add_option("--dims", encode.dims, "X Y Z extents of every input volume")->expected(3);
  encodeCmd->add_option("--type", encode.type, "voxel type of the inputs: uint8, or uint16 (leb; little endian)")->default_val("uint8");
  encodeCmd->add_flag("--plume", encode.plume, "encode the synthetic discharge plume instead of files");
  encodeCmd->add_option("--sparseness", encode.sparseness, "plume: fraction of zero voxels to aim for (e.g. 0.9965)");
  encodeCmd->add_option("--side", encode.plumeSide, "plume: volume side (power of two)")->default_val(128);
  encodeCmd->add_option("--steps", encode.plumeSteps, "plume: time steps")->default_val(36);
  encodeCmd->add_option("--tf", encode.transfer, "transfer function: plume, opaque, gray")->default_val("plume");
  encodeCmd->add_option("--level", encode.level, "subdivision level, or auto (the level whose file is smallest)")->default_val("auto");
  encodeCmd->add_option("--encoding", encode.encoding, "index encoding: normalized_rgba8 (paper), normalized_rgba16, normalized_float, block_rgba8")
      ->default_val("normalized_rgba8");
  encodeCmd->add_option("--alpha-one", encode.alphaOne, "homogeneous colours with alpha 255: refine (lossless) or paper")->default_val("refine");
  encodeCmd->add_option("--page-bits", encode.pageBits, "leb: pages of 2^N points (4..20)")->default_val(12);
  encodeCmd->add_flag("--no-gradients", encode.noGradients, "leb: code the data only, no gradients channel");
  encodeCmd->add_option("--bounds-out", encode.boundsOut, "leb: also write the per-diamond min, max and error for isosurfaces (.vxlbb)");
  encodeCmd->add_option("--out", encode.out, "output file (.vxtv, .vxleb)")->required();

  DecodeOptions decode;
  auto* decodeCmd = app.add_subcommand("decode", "decode a codec file into raw volumes");
  decodeCmd->add_option("--codec", decode.codec, "timevarying or leb")->required();
  decodeCmd->add_option("--input", decode.input, "file to decode")->required();
  decodeCmd->add_option("--out", decode.out,
                        "timevarying: output directory (step_NNN.rgba: RGBA8 voxels, x fastest); leb: the raw volume file")->required();
  decodeCmd->add_option("--step", decode.step, "timevarying: only this time step (0-based; default: every step)");
  decodeCmd->add_option("--gradients-out", decode.gradientsOut, "leb: also write the gradients (3 int8 per sample, x fastest)");

  InfoOptions info;
  auto* infoCmd = app.add_subcommand("info", "describe a codec file: layout, padding, statistics");
  infoCmd->add_option("--codec", info.codec, "timevarying or leb")->required();
  infoCmd->add_option("--input", info.input, "file to describe")->required();

  FixturesOptions fixtures;
  auto* fixturesCmd = app.add_subcommand("fixtures", "Embree ground truth of the isosurface scenes: generate, or verify bit for bit");
  fixturesCmd->require_subcommand(1);
  for (const bool generate : {true, false}) {
    auto* sub = fixturesCmd->add_subcommand(generate ? "generate" : "verify",
                                            generate ? "write EXR fixtures and a manifest with sha256 of every file" : "regenerate from the manifest and compare every file");
    sub->add_option("--dir", fixtures.dir, "fixture directory (holds manifest.json)")->required();
    sub->add_option("--threads", fixtures.threads, "CPU threads (0: all); results are the same for any count")->default_val(0);
    if (!generate) continue;
    sub->callback([&fixtures] { fixtures.generate = true; });
    sub->add_option("--scene", fixtures.scene, "built-in scene (iso.frames.<scene>), or all")->default_val("all");
    sub->add_option("--frames", fixtures.frames, "frames of the orbit (default: the scene's)")
        ->check(CLI::Range(1, voxref::conf::kMaxIsoSceneFrames));  // the bound the manifest reader applies
    sub->add_option("--volume", fixtures.volume, "your raw volume (.raw or .raw.gz) instead of a built-in scene");
    sub->add_option("--dims", fixtures.dims, "X Y Z of --volume")->expected(3);
    sub->add_option("--type", fixtures.type, "voxel type of --volume: uint8 or uint16 (little endian)")->default_val("uint8");
    sub->add_option("--isovalue", fixtures.isovalue, "isovalue for --volume (or to override the scene's)")->check(finiteNumber);
  }

  CheckShaderOptions checkShader;
  auto* checkShaderCmd = app.add_subcommand("check-shader", "run one case with your fragment shader in place of the built-in stage");
  checkShaderCmd->add_option("--case", checkShader.caseId, "case id from voxref list")->required();
  checkShaderCmd->add_option("--shader", checkShader.shader, "your GLSL fragment shader, without #version (docs/shader-interface.md)");
  checkShaderCmd->add_flag("--print-interface", checkShader.printInterface, "print the case's stage: its interface and the built-in shader");
  checkShaderCmd->add_option("--driver", checkShader.driver, "llvmpipe, softpipe or egl")->default_val("llvmpipe");
  checkShaderCmd->add_option("--profile", checkShader.profile, "auto or a precision profile name")->default_val("auto");
  checkShaderCmd->add_option("--out", checkShader.out, "report directory (results.json, junit.xml, index.html)")->default_val("voxref-check-shader");
  checkShaderCmd->add_option("--threads", checkShader.threads, "CPU threads for emulation and reference (0: all)")->default_val(0);

  ProbeOptions probe;
  auto* probeCmd = app.add_subcommand("probe", "infer the driver's precision from probe frames and match it to the known profiles");
  probeCmd->add_option("--driver", probe.driver, "llvmpipe, softpipe or egl")->default_val("llvmpipe");
  probeCmd->add_option("--out", probe.out, "also write the fingerprint as JSON");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (*listCmd) return runList(list);
    if (*conformCmd) {
      conform.command = joinArgs(argc, argv);
      return runConform(conform);
    }
    if (*renderCmd) return runRender(render);
    if (*benchCmd) return runBench(bench);
    if (*encodeCmd) return runEncode(encode);
    if (*decodeCmd) return runDecode(decode);
    if (*infoCmd) return runInfo(info);
    if (*fixturesCmd) return runFixtures(fixtures);
    if (*probeCmd) return runProbe(probe);
    if (*checkShaderCmd) {
      checkShader.command = joinArgs(argc, argv);
      return runCheckShader(checkShader);
    }
  } catch (const std::exception& e) {
    std::cerr << "voxref: " << e.what() << "\n";
    return 2;
  }
  return 2;
}
