#include <fstream>
#include <iostream>
#include <memory>

#include "conformance/cli/commands.h"
#include "conformance/framework/driver_info.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/progress.h"
#include "conformance/io/atomic_file.h"
#include "conformance/io/image_io.h"
#include "conformance/modules/catalog.h"
#include "conformance/modules/sparsegrid/prepared_scene.h"
#include "conformance/modules/timevarying/timevarying_scene.h"
#include "emulation/combination_emu.h"
#include "emulation/timevarying_emu.h"
#include "gpu/combination_gl.h"
#include "gpu/timevarying_gl.h"
#include "reference/common/framebuffer_codes.h"
#include "reference/timevarying/exact_colours.h"

namespace voxref::cli {
namespace {

struct RenderOptions {
  std::string scene;  // a scene JSON file or a case id
  std::string backend = "reference";
  std::string driver = "llvmpipe";
  std::string profile = "llvmpipe";  // for the emulation backend ("auto": from --driver's context)
  std::filesystem::path out;
  int threads = 0;
};

namespace {

// A scene JSON file, or the scene of a built-in case.
nlohmann::json loadScene(const std::string& spec) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(spec, ec)) {
    std::ifstream in(spec);
    try {
      return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for a number beyond double
      throw conf::UsageError("scene file " + spec + " is not valid JSON: " + e.what());
    }
  }
  for (const conf::Case& c : conf::allCases())
    if (c.id == spec) {
      if (!c.scene) throw conf::UsageError("case " + spec + " has no single scene to render");
      return *c.scene;
    }
  throw conf::UsageError("'" + spec + "' is neither a scene file nor a case id (voxref list shows the cases)");
}

// A time-varying scene: the composite of its first time step (back-to-front slices), RGBA.
int renderTimeVarying(const RenderOptions& o, const conf::TimeVaryingScene& scene) {
  const ref::TimeSeries series = conf::makeSeries(scene);
  const ref::TransferFunction tf = ref::transferFunction(scene.transfer);
  const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(series, tf, scene.encoding);
  const ref::PlaneFrame frame = conf::makeFrame(scene, tex.layout);
  const int step = conf::stepsOf(scene).front();
  std::map<std::string, std::string> attributes{{"voxref.scene", conf::toJson(scene).dump()},
                                                {"voxref.backend", o.backend},
                                                {"voxref.step", std::to_string(step)}};
  std::vector<std::array<double, 4>> rgba(static_cast<std::size_t>(frame.width) * frame.height, {0, 0, 0, 0});
  if (o.backend == "reference") {
    // The input's colours composited back to front in real arithmetic (reference/timevarying/exact_colours.h).
    rgba = ref::idealComposite(ref::exactColours(series, tf, step, frame), frame);
    for (auto& px : rgba)
      for (double& v : px) v /= 255.0;
  } else {
    ref::RgbaStack image;
    if (o.backend == "emulation") {
      const emu::PrecisionProfile* profile = emu::findProfile(o.profile);
      if (!profile) throw conf::UsageError("unknown profile '" + o.profile + "'");
      image = emu::emulateComposite(tex, scene.decoder, step, frame, *profile, o.threads);
      attributes["voxref.profile"] = std::string(profile->name);
    } else if (o.backend == "gl") {
      const auto driver = gpu::parseDriver(o.driver);
      if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "'");
      const auto context = gpu::createContext(*driver);
      image = gpu::compositeGl(*context, tex, scene.decoder, step, frame);
      attributes["voxref.renderer"] = context->info().renderer + " " + context->info().version;
    } else {
      throw conf::UsageError("unknown backend '" + o.backend + "' (reference, emulation or gl)");
    }
    for (std::size_t i = 0; i < rgba.size(); ++i)
      for (int ch = 0; ch < 4; ++ch) rgba[i][ch] = image.colours[i][ch] / 255.0;
  }
  std::vector<io::ExrChannel> channels{{"R", {}}, {"G", {}}, {"B", {}}, {"A", {}}};
  for (int ch = 0; ch < 4; ++ch) {
    channels[ch].data.resize(rgba.size());
    for (int j = 0; j < frame.height; ++j)
      for (int i = 0; i < frame.width; ++i)
        channels[ch]
            .data[static_cast<std::size_t>(i) + static_cast<std::size_t>(frame.width) * (frame.height - 1 - j)] =
            static_cast<float>(rgba[static_cast<std::size_t>(i) + static_cast<std::size_t>(frame.width) * j][ch]);
  }
  io::writeExr(o.out, frame.width, frame.height, channels, attributes);
  std::cout << "wrote " << o.out.string() << " (" << frame.width << "x" << frame.height << ", " << o.backend << ")\n";
  return 0;
}

}  // namespace

int runRender(const RenderOptions& o) {
  if (o.out.extension() != ".exr") throw conf::UsageError("--out must name an .exr file, got " + o.out.string());
  const nlohmann::json json = loadScene(o.scene);
  if (json.is_object() && json.contains("system") &&
      json["system"] == "timevarying") {  // value() would throw for a non-string
    try {
      return renderTimeVarying(o, conf::parseTimeVaryingScene(json));
    } catch (const conf::JsonFieldError& e) {
      throw conf::UsageError("scene " + o.scene + ": " + e.what());
    }
  }
  conf::SparseGridScene scene;
  try {
    scene = conf::parseSparseGridScene(json);
  } catch (const conf::SceneError& e) {
    throw conf::UsageError("scene " + o.scene + ": " + e.what());
  }
  // What only preparing the scene finds (its camera frame, pass order and volume file) is named
  // with the scene file too.
  const conf::PreparedScene prepared = [&] {
    try {
      return conf::prepareScene(scene);
    } catch (const conf::SceneError& e) {
      throw conf::UsageError("scene " + o.scene + ": " + e.what());
    } catch (const io::IoError& e) {
      throw io::IoError("scene " + o.scene + ": data.volume: " + e.what());
    }
  }();
  conf::Progress progress("voxref render (" + o.backend + ")", prepared.frame.planes);
  auto onPlane = [&](int done) { progress.update(done); };
  ref::SampleStack samples;
  std::map<std::string, std::string> attributes{{"voxref.scene", conf::toJson(scene).dump()},
                                                {"voxref.backend", o.backend}};
  if (o.backend == "reference") {
    samples = conf::referencePlanes(prepared, o.threads, onPlane);
  } else if (o.backend == "emulation") {
    const emu::PrecisionProfile* profile = emu::findProfile(o.profile);
    if (!profile) throw conf::UsageError("unknown profile '" + o.profile + "'");
    const auto planes = emu::emulateCombination(prepared.textures, prepared.frame, scene.sampler, scene.framebuffer,
                                                *profile, {scene.flushEachPass, o.threads}, onPlane);
    samples = ref::toSampleStack(planes.planes, prepared.textures.readbackScale);
    attributes["voxref.profile"] = std::string(profile->name);
  } else if (o.backend == "gl") {
    const auto driver = gpu::parseDriver(o.driver);
    if (!driver) throw conf::UsageError("unknown driver '" + o.driver + "'");
    const auto context = gpu::createContext(*driver);
    const auto planes = gpu::renderCombinationGl(*context, prepared.textures, prepared.frame, scene.sampler,
                                                 scene.framebuffer, {scene.flushEachPass}, onPlane);
    samples = ref::toSampleStack(planes, prepared.textures.readbackScale);
    attributes["voxref.renderer"] = context->info().renderer + " " + context->info().version;
  } else {
    throw conf::UsageError("unknown backend '" + o.backend + "' (reference, emulation or gl)");
  }
  progress.finish();
  const ref::Image image = ref::shadePlanes(samples, prepared.frame, scene.shading);
  io::ExrChannel y{"Y", std::vector<float>(image.pixels.size())};
  for (int j = 0; j < image.height; ++j)  // EXR rows run top to bottom
    for (int i = 0; i < image.width; ++i)
      y.data[static_cast<std::size_t>(i) + static_cast<std::size_t>(image.width) * (image.height - 1 - j)] =
          static_cast<float>(image.pixels[static_cast<std::size_t>(i) + static_cast<std::size_t>(image.width) * j]);
  io::writeExr(o.out, image.width, image.height, {y}, attributes);
  std::cout << "wrote " << o.out.string() << " (" << image.width << "x" << image.height << ", " << o.backend << ")\n";
  return 0;
}

}  // namespace

Subcommand addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* sub = app.add_subcommand("render", "render one scene with one backend into an EXR image");
  sub->add_option("--scene", o->scene, "scene JSON file, or a case id from voxref list")->required();
  sub->add_option("--backend", o->backend, "reference, emulation or gl")->default_val("reference");
  sub->add_option("--driver", o->driver, "GL driver for the gl backend")->default_val("llvmpipe");
  sub->add_option("--profile", o->profile, "precision profile for the emulation backend")->default_val("llvmpipe");
  sub->add_option("--out", o->out, "output image (.exr)")->required();
  sub->add_option("--threads", o->threads, "CPU threads (0: all)")->default_val(0);

  return {sub, [o] { return runRender(*o); }};
}

}  // namespace voxref::cli
