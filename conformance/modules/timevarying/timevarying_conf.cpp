#include "conformance/modules/timevarying/timevarying_conf.h"
#include "conformance/framework/compare.h"
#include "conformance/framework/stopwatch.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "conformance/io/atomic_file.h"
#include "conformance/framework/report/case_images.h"
#include "conformance/modules/timevarying/fetch_classification.h"
#include "conformance/modules/timevarying/timevarying_envelope_conf.h"
#include "emulation/framebuffer_emu.h"
#include "emulation/timevarying_emu.h"
#include "reference/timevarying/exact_colours.h"
#include "reference/timevarying/plume.h"
#include "gpu/gl_error.h"
#include "gpu/timevarying_gl.h"

namespace voxref::conf {
namespace {


io::Rgb8Image rgbPreview(const ref::RgbaStack& s, int plane) {
  io::Rgb8Image img{s.width, s.height, std::vector<std::uint8_t>(static_cast<std::size_t>(s.width) * s.height * 3)};
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      const ref::Rgba8& c = s.at(i, j, plane);
      std::uint8_t* px = &img.rgb[3 * (static_cast<std::size_t>(i) + static_cast<std::size_t>(s.width) * (s.height - 1 - j))];
      px[0] = c[0], px[1] = c[1], px[2] = c[2];
    }
  return img;
}

// Error mask of the first step (case_images.h colours, every plane collapsed onto its pixel): red
// where GL and emulation differ, magenta outside the envelope, yellow only inside the quality-warning
// envelope; blue where no oracle flags the pixel but the judged colour differs from the exact decoder
// (the paper's traps); elsewhere the shown plane's luminance, dimmed.
io::Rgb8Image maskPreview(const ref::RgbaStack& judged, const ref::RgbaStack& exact, int plane, const std::vector<PixelFlag>& flags) {
  ref::Image base{judged.width, judged.height, std::vector<double>(static_cast<std::size_t>(judged.width) * judged.height)};
  for (int j = 0; j < judged.height; ++j)
    for (int i = 0; i < judged.width; ++i) {
      const ref::Rgba8& c = judged.at(i, j, plane);
      base.pixels[static_cast<std::size_t>(i) + static_cast<std::size_t>(judged.width) * j] = (0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]) / 255.0;
    }
  io::Rgb8Image img = errorMaskPreview(base, 1.0, flags);
  for (int j = 0; j < judged.height; ++j)
    for (int i = 0; i < judged.width; ++i) {
      if (flags[static_cast<std::size_t>(i) + static_cast<std::size_t>(judged.width) * j] != PixelFlag::None) continue;
      bool differs = false;
      for (int k = 0; k < judged.planes && !differs; ++k) differs = judged.at(i, j, k) != exact.at(i, j, k);
      std::uint8_t* px = &img.rgb[3 * (static_cast<std::size_t>(i) + static_cast<std::size_t>(judged.width) * (judged.height - 1 - j))];
      if (differs) px[0] = 40, px[1] = 90, px[2] = 255;
    }
  return img;
}


}  // namespace

CaseResult judgeTimeVarying(CaseContext& ctx, const std::string& id, const std::string& description, const TimeVaryingScene& scene,
                            const TimeVaryingExpectation& expect) {
  CaseResult result;
  result.id = id;
  result.system = "timevarying";
  result.description = description;
  auto t0 = Clock::now();
  const auto series = ctx.cached<ref::TimeSeries>("timevarying:" + seriesKey(scene),
                                                  [&] { return std::make_shared<ref::TimeSeries>(makeSeries(scene)); });
  const ref::TransferFunction tf = ref::transferFunction(scene.transfer);
  const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(*series, tf, scene.encoding);
  result.secondsReference += secondsSince(t0);
  const ref::PlaneFrame frame = makeFrame(scene, tex.layout);
  const ref::EncodeStats& st = tex.stats;
  result.figures = {{"scene", toJson(scene)},
                    {"index_bytes", st.indexBytes},
                    {"refinement_bytes", st.refinementBytes},
                    {"ratio_against_4_bytes", st.ratioAgainst4Bytes()},
                    {"distinct_blocks", st.distinctBlocks},
                    {"hash_hits", st.hashHits},
                    {"hash_collisions", st.hashCollisions},
                    {"alpha_one_cells", st.alphaOneCells},
                    {"sparseness", ref::sparseness(*series)}};
  const emu::PrecisionProfile* profile = ctx.profile();
  std::vector<emu::Effect> simulated;
  if (profile) {
    simulated = emu::TimeVaryingDecoderEmu(tex, scene.decoder, *profile).effects();
    simulated.push_back(emu::Effect::OutputUnorm8);
    if (scene.composite)
      for (emu::Effect e : emu::AlphaBlendEmu(*profile).effects()) simulated.push_back(e);
    for (emu::Effect e : simulated) result.effects.emplace_back(emu::effectId(e));
  }

  std::size_t compared = 0, mismatched = 0, wrongColours = 0, samples = 0;
  int maxExactDiff = 0, maxIdealDiff = 0;
  double idealSumSq = 0.0;
  FetchCounts fetches;
  std::vector<std::size_t> departureChanges;
  const std::vector<emu::Departure> departures = profile ? emu::departuresAmong(*profile, simulated) : std::vector<emu::Departure>{};
  departureChanges.assign(departures.size(), 0);
  std::string glNotRun;
  std::optional<ref::RgbaStack> firstGl, firstEmu, firstExact;
  TimeVaryingEnvelopeOracle envelopeOracle(tex, scene.decoder, frame, scene.composite);
  std::vector<PixelFlag> flags(static_cast<std::size_t>(frame.width) * frame.height, PixelFlag::None);
  const std::vector<int> steps = stepsOf(scene);
  for (int step : steps) {
    std::optional<ref::RgbaStack> gl;
    if (ctx.gl() && glNotRun.empty()) try {
        t0 = Clock::now();
        gl = scene.composite ? gpu::compositeGl(*ctx.gl(), tex, scene.decoder, step, frame, {}, ctx.shaderOverride())
                             : gpu::decodePlanesGl(*ctx.gl(), tex, scene.decoder, step, frame, {}, ctx.shaderOverride());
        result.secondsGl += secondsSince(t0);
      } catch (const gpu::GlUnsupported& e) {
        glNotRun = e.what();
      }
    else if (!ctx.gl())
      glNotRun = "no GL context in this run";
    std::optional<ref::RgbaStack> emulated;
    if (profile) {
      t0 = Clock::now();
      const emu::EmulatedDecode decoded = emu::emulateDecodePlanes(tex, scene.decoder, step, frame, *profile, ctx.threads());
      emulated = scene.composite ? emu::emulateComposite(tex, scene.decoder, step, frame, *profile, ctx.threads()) : decoded.colours;
      result.secondsEmulation += secondsSince(t0);
      fetches.add(classifyFetches(tex, *series, tf, step, frame, decoded));
    }
    t0 = Clock::now();
    const ref::RgbaStack exact = ref::exactColours(*series, tf, step, frame);
    ref::RgbaStack reference = exact;
    if (scene.composite) {
      const auto ideal = ref::idealComposite(exact, frame);
      reference = {frame.width, frame.height, 1, {}};
      for (const auto& c : ideal)
        reference.colours.push_back({static_cast<std::uint8_t>(std::lround(c[0])), static_cast<std::uint8_t>(std::lround(c[1])),
                                     static_cast<std::uint8_t>(std::lround(c[2])), static_cast<std::uint8_t>(std::lround(c[3]))});
      if (gl)
        for (std::size_t i = 0; i < ideal.size(); ++i)
          for (int c = 0; c < 4; ++c) {
            const double d = gl->colours[i][c] - ideal[i][c];
            idealSumSq += d * d;
            maxIdealDiff = std::max(maxIdealDiff, static_cast<int>(std::ceil(std::fabs(d) - 1e-9)));
          }
    }
    result.secondsReference += secondsSince(t0);
    if (gl)
      for (std::size_t d = 0; d < departures.size(); ++d) {
        const ref::RgbaStack semantics =
            scene.composite
                ? emu::emulateComposite(tex, scene.decoder, step, frame, departures[d].semantics, ctx.threads(), departures[d].flushEachPass)
                : emu::emulateDecodePlanes(tex, scene.decoder, step, frame, departures[d].semantics, ctx.threads()).colours;
        for (std::size_t i = 0; i < gl->colours.size(); ++i) departureChanges[d] += gl->colours[i] != semantics.colours[i];
      }
    const ref::RgbaStack* judged = gl ? &*gl : emulated ? &*emulated : nullptr;
    if (gl && emulated)
      for (std::size_t i = 0; i < gl->colours.size(); ++i) {
        ++compared;
        if (gl->colours[i] != emulated->colours[i]) {
          ++mismatched;
          maxExactDiff = std::max(maxExactDiff, largestChannelDifference(gl->colours[i], emulated->colours[i]).difference);
        }
      }
    if (judged && !scene.composite)
      for (std::size_t i = 0; i < judged->colours.size(); ++i) {
        ++samples;
        if (judged->colours[i] != reference.colours[i]) {
          ++wrongColours;
          maxIdealDiff = std::max(maxIdealDiff, largestChannelDifference(judged->colours[i], reference.colours[i]).difference);
        }
      }
    if (scene.composite && judged) samples += judged->colours.size();
    envelopeOracle.add(step, gl ? &*gl : nullptr, emulated ? &*emulated : nullptr, reference, ctx.threads(), firstExact ? nullptr : &flags);
    if (!firstExact) {
      firstExact = reference;
      if (gl) firstGl = gl;
      if (emulated) firstEmu = emulated;
    }
  }

  for (std::size_t d = 0; d < departures.size(); ++d)
    result.findings.push_back({std::string(departures[d].id), std::string(departures[d].description),
                               {{"samples_changed", departureChanges[d]}, {"pixels_compared", samples}}});
  OracleResult exact{"exact", Verdict::NotRun, "", nlohmann::json::object()};
  if (!glNotRun.empty() || !profile) {
    exact.summary = !glNotRun.empty() ? "GL not run: " + glNotRun : "no precision profile for this driver";
  } else {
    exact.verdict = mismatched ? Verdict::Fail : Verdict::Pass;
    exact.figures = {{"compared_samples", compared}, {"mismatched_samples", mismatched}, {"mismatched_pixels", mismatched},
                     {"max_abs_diff_lsb", maxExactDiff}, {"steps", steps.size()}};
    exact.summary = std::to_string(mismatched) + " of " + std::to_string(compared) + " RGBA samples differ over " +
                    std::to_string(steps.size()) + " time step(s)";
  }
  OracleResult fetch{"fetch", Verdict::NotRun, "", nlohmann::json::object()};
  if (profile) {
    fetch.figures = fetches.toJson();
    const bool clean = fetches.wrong() == 0 && fetches.wrongColour == 0;
    fetch.verdict = expect.everyFetchRight ? (clean ? Verdict::Pass : Verdict::Fail)
                    : expect.trapReproduced ? (fetches.wrongColour > 0 ? Verdict::Pass : Verdict::Fail)
                                            : Verdict::Info;
    fetch.summary = std::to_string(fetches.wrong()) + " of " + std::to_string(fetches.samples) + " fetches wrong (" +
                    std::to_string(fetches.wrongBlock) + " wrong block, " + std::to_string(fetches.wrongVoxel) + " wrong voxel; " +
                    std::to_string(fetches.atCoordinateOne) + " at 1.0, " + std::to_string(fetches.onBlockFace) + " on block faces, " +
                    std::to_string(fetches.onVoxelFace) + " on voxel faces, " + std::to_string(fetches.inside) + " inside); " +
                    std::to_string(fetches.wrongColour) + " wrong colours" +
                    (expect.everyFetchRight ? " (must be 0)" : expect.trapReproduced ? " (the paper's trap must show)" : "");
  } else {
    fetch.summary = "no precision profile: the fetches are known only through the emulation";
  }
  OracleResult ideal{"ideal", Verdict::Info, "", nlohmann::json::object()};
  if (scene.composite) {
    const double rmse = samples ? std::sqrt(idealSumSq / (4.0 * static_cast<double>(samples))) : 0.0;
    ideal.figures = {{"max_abs_diff_lsb", maxIdealDiff}, {"rmse", rmse}, {"pixels", samples}};
    ideal.summary = "composited image vs the exact colours composited in real arithmetic: max " + std::to_string(maxIdealDiff) +
                    " LSB, RMSE " + std::to_string(rmse) + " LSB";
  } else {
    ideal.figures = {{"wrong_colours", wrongColours}, {"samples", samples}, {"max_abs_diff_lsb", maxIdealDiff}, {"rmse", nullptr}};
    ideal.summary = std::to_string(wrongColours) + " of " + std::to_string(samples) + " samples decode another colour than the exact decoder" +
                    (wrongColours ? " (max channel difference " + std::to_string(maxIdealDiff) + ")" : "");
  }
  const OracleResult envelope = envelopeOracle.result();
  result.worstPixels = envelopeOracle.worstPixels();
  result.oracles = {exact, envelope, fetch, ideal};
  concludeFromOracles(result);
  if (!glNotRun.empty() && ctx.gl()) {
    result.status = Status::Skip;
    result.message = glNotRun;
  }
  if ((ctx.writeAllImages() || result.status == Status::Fail || result.status == Status::Warn) && firstExact) {
    const int plane = scene.composite ? 0 : firstExact->planes / 2;
    io::ensureDirectory(ctx.outDir() / "images");
    auto write = [&](const ref::RgbaStack& s, const std::string& kind, std::string& slot) {
      slot = caseImageName(id, kind);
      io::writePng(ctx.outDir() / slot, rgbPreview(s, plane));
    };
    if (firstGl) write(*firstGl, "rendered", result.images.rendered);
    if (firstEmu) write(*firstEmu, "emulated", result.images.emulated);
    write(*firstExact, "reference", result.images.reference);
    if (firstGl || firstEmu) {
      result.images.errorMask = caseImageName(id, "error_mask");
      io::writePng(ctx.outDir() / result.images.errorMask, maskPreview(firstGl ? *firstGl : *firstEmu, *firstExact, plane, flags));
    }
  }
  return result;
}

Case timeVaryingCase(std::string id, std::string description, TimeVaryingScene scene, TimeVaryingExpectation expectation) {
  Case c;
  c.id = id;
  c.system = "timevarying";
  c.description = description;
  c.run = [id, description, scene, expectation](CaseContext& ctx) { return judgeTimeVarying(ctx, id, description, scene, expectation); };
  c.scene = toJson(scene);
  return c;
}

}  // namespace voxref::conf
