// study.sparsegrid: the precision variants of the combination technique on one scene, each against
// the double combination technique (eq. 11 of Teitzel et al. 1999) at the same sample points.
#include <cmath>
#include <optional>

#include "conformance/bench/sparsegrid_bench.h"
#include "conformance/bench/study.h"
#include "conformance/framework/compare.h"
#include "conformance/framework/progress.h"
#include "conformance/modules/sparsegrid/prepared_scene.h"
#include "conformance/modules/sparsegrid/sparsegrid_catalog.h"
#include "emulation/combination_emu.h"
#include "gpu/combination_gl.h"
#include "gpu/gl_error.h"
#include "reference/common/parallel.h"
#include "reference/common/texel_format.h"

namespace voxref::conf {
namespace {

double framebufferBytesPerPixel(ref::FramebufferFormat f) {
  switch (f) {
    case ref::FramebufferFormat::RGBA16F:
      return 8.0;
    case ref::FramebufferFormat::RGBA32F:
      return 16.0;
    default:
      return 4.0 * ref::unormBits(f) / 8.0;  // rgba12: its nominal 48 bits
  }
}

// The error figures of read-back planes against the double reference.
StudyVariant judged(const std::string& name, const ref::CodePlanes& planes, const PreparedScene& prepared,
                    const ref::SampleStack& reference) {
  const ref::SampleStack values = ref::toSampleStack(planes, prepared.textures.readbackScale);
  const ErrorFigures e = compareValues(values.values, reference.values, 1.0);
  StudyVariant v;
  v.name = name;
  v.error = e.rmse;
  v.figures = {{"rmse", e.rmse},
               {"max_abs_error", e.maxAbs},
               {"psnr_db", std::isfinite(e.psnrDb) ? nlohmann::json(e.psnrDb) : nlohmann::json("inf")}};
  return v;
}

struct Scene {
  SparseGridScene scene;
  PreparedScene prepared;
  ref::SampleStack reference;
};

Scene makeScene(const BenchOptions& o, ref::TexelFormat texels, ref::FramebufferFormat fb) {
  Scene s;
  s.scene = defaultSparseGridScene();
  s.scene.grid.level = o.quick ? 4 : 7;
  s.scene.textures.format = texels;
  s.scene.framebuffer = fb;
  s.scene.shading.mode = ref::RenderMode::XRay;
  s.scene.width = s.scene.height = o.quick ? 24 : 96;
  s.scene.planes = o.quick ? 12 : 48;
  s.prepared = prepareScene(s.scene);
  s.reference = referencePlanes(s.prepared, o.threads);
  return s;
}

// One variant drawn on GL: error of its read-back, GL time, textures + one plane's colour buffer.
StudyVariant onGl(const std::string& name, gpu::Context& gl, const Scene& s, ref::FramebufferFormat fb) {
  std::optional<ref::CodePlanes> planes;
  Timing t;
  try {
    t = measure(
        [&] { planes = gpu::renderCombinationGl(gl, s.prepared.textures, s.prepared.frame, s.scene.sampler, fb); },
        kStudyRuns);
  } catch (const gpu::GlUnsupported& e) {
    StudyVariant v;
    v.name = name;
    v.missing = std::string("not on this GL: ") + e.what();
    return v;
  }
  StudyVariant v = judged(name, *planes, s.prepared, s.reference);
  v.time = t;
  v.memoryBytes = static_cast<double>(ref::textureBytes(s.prepared.textures)) +
                  framebufferBytesPerPixel(fb) * s.scene.width * s.scene.height;
  return v;
}

// One variant emulated under `profile`: error of the emulated planes, emulation time.
StudyVariant emulated(const std::string& name, const Scene& s, ref::FramebufferFormat fb,
                      const emu::PrecisionProfile& profile, int threads) {
  std::optional<ref::CodePlanes> planes;
  const Timing t = measure(
      [&] {
        planes = emu::emulateCombination(s.prepared.textures, s.prepared.frame, s.scene.sampler, fb, profile,
                                         {false, threads})
                     .planes;
      },
      kStudyRuns);
  StudyVariant v = judged(name, *planes, s.prepared, s.reference);
  v.time = t;
  v.memoryBytes = static_cast<double>(ref::textureBytes(s.prepared.textures)) +
                  framebufferBytesPerPixel(fb) * s.scene.width * s.scene.height;
  return v;
}

}  // namespace

BenchTable sparseGridStudy(const BenchOptions& o, gpu::Context& gl, const emu::PrecisionProfile* profile) {
  using FB = ref::FramebufferFormat;
  using TF = ref::TexelFormat;
  const std::string error = "RMSE of the read-back samples against the double combination technique (values in [0, 1])";
  const std::string memory = "textures + one plane's colour buffer";
  const std::string glTime = "GL frame on " + gl.info().renderer + ", read-back included";
  Progress progress("voxref bench study.sparsegrid", 13 + static_cast<long>(emu::knownProfiles().size()));
  long step = 0;

  StudyGroup framebuffers{"framebuffer format (r16 textures)", error, glTime, memory, false, {}, ""};
  const Scene r16 = makeScene(o, TF::R16, FB::RGBA8);
  for (FB fb : {FB::RGBA8, FB::RGBA12, FB::RGBA16, FB::RGBA16F, FB::RGBA32F}) {
    progress.update(step++, "framebuffer " + std::string(ref::name(fb)));
    if (ref::existsInGl(fb)) {
      framebuffers.variants.push_back(onGl(std::string(ref::name(fb)), gl, r16, fb));
    } else if (profile) {  // GL has no such buffer: its error from the emulation, no GL time
      StudyVariant v = emulated(std::string(ref::name(fb)), r16, fb, *profile, o.threads);
      v.time = {};
      v.missing = "no GL implementation: error emulated, not timed";
      framebuffers.variants.push_back(v);
    }
  }
  framebuffers.note =
      "rgba12 (the paper's 12-bit buffer) exists in no GL here; its error comes from the emulation under the driver's "
      "profile.";

  StudyGroup textures{"texture format (rgba32f framebuffer)", error, glTime, memory, false, {}, ""};
  for (TF tf : {TF::R8, TF::R16, TF::R16F, TF::R32F}) {
    progress.update(step++, "texture " + std::string(ref::name(tf)));
    textures.variants.push_back(
        onGl(std::string(ref::name(tf)), gl, tf == TF::R16 ? r16 : makeScene(o, tf, FB::RGBA32F), FB::RGBA32F));
  }

  StudyGroup paths{"sampler path and rounding, per profile (r8 textures, rgba32f framebuffer)",
                   error,
                   "emulated frame (CPU, " + std::to_string(ref::workerCount(o.threads)) + " thread(s))",
                   memory,
                   false,
                   {},
                   ""};
  const Scene r8 = makeScene(o, TF::R8, FB::RGBA32F);
  for (const emu::PrecisionProfile& p : emu::knownProfiles()) {
    progress.update(step++, "profile " + std::string(p.name));
    paths.variants.push_back(emulated(std::string(p.name), r8, FB::RGBA32F, p, o.threads));
  }
  paths.note =
      "One process holds one GL driver, so the sampler paths of the other drivers and settings (llvmpipe's 8-bit AoS "
      "filtering, its float SoA path under GALLIVM_PERF=no_aos_sampling, softpipe) are run through their emulations, "
      "which "
      "equal the drivers bit for bit (voxref conform, voxref probe); their times are the emulator's, not the drivers'.";
  progress.finish();
  const auto& sc = r16.scene;
  return studyTable(
      "study.sparsegrid",
      "Study, sparse grids (level " + std::to_string(sc.grid.level) + ", " + std::to_string(sc.width) + "x" +
          std::to_string(sc.height) + "x" + std::to_string(sc.planes) +
          " samples, Gaussian blobs, LINEAR, padded textures)",
      {framebuffers, textures, paths},
      "Every variant renders the same samples; errors are against the double combination technique at those samples.");
}

}  // namespace voxref::conf
