#include "conformance/modules/timevarying/timevarying_conf.h"
#include "conformance/framework/compare.h"
#include "conformance/framework/stopwatch.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "conformance/framework/report/case_images.h"
#include "conformance/io/atomic_file.h"
#include "conformance/modules/timevarying/fetch_classification.h"
#include "conformance/modules/timevarying/timevarying_envelope_conf.h"
#include "emulation/framebuffer_emu.h"
#include "emulation/timevarying_emu.h"
#include "gpu/gl_error.h"
#include "gpu/timevarying_gl.h"
#include "reference/timevarying/exact_colours.h"
#include "reference/timevarying/plume.h"

namespace voxref::conf {
namespace {

io::Rgb8Image rgbPreview(const ref::RgbaStack& s, int plane) {
  io::Rgb8Image img{s.width, s.height, std::vector<std::uint8_t>(static_cast<std::size_t>(s.width) * s.height * 3)};
  for (int j = 0; j < s.height; ++j)
    for (int i = 0; i < s.width; ++i) {
      const ref::Rgba8& c = s.at(i, j, plane);
      std::uint8_t* px =
          &img.rgb[3 * (static_cast<std::size_t>(i) + static_cast<std::size_t>(s.width) * (s.height - 1 - j))];
      px[0] = c[0], px[1] = c[1], px[2] = c[2];
    }
  return img;
}

// Error mask of the first step (case_images.h colours, every plane collapsed onto its pixel): red
// where GL and emulation differ, magenta outside the envelope, yellow only inside the quality-warning
// envelope; blue where no oracle flags the pixel but the judged colour differs from the exact decoder
// (the paper's traps); elsewhere the shown plane's luminance, dimmed.
io::Rgb8Image maskPreview(const ref::RgbaStack& judged, const ref::RgbaStack& exact, int plane,
                          const std::vector<PixelFlag>& flags) {
  ref::Image base{judged.width, judged.height,
                  std::vector<double>(static_cast<std::size_t>(judged.width) * judged.height)};
  for (int j = 0; j < judged.height; ++j)
    for (int i = 0; i < judged.width; ++i) {
      const ref::Rgba8& c = judged.at(i, j, plane);
      base.pixels[static_cast<std::size_t>(i) + static_cast<std::size_t>(judged.width) * j] =
          (0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]) / 255.0;
    }
  io::Rgb8Image img = errorMaskPreview(base, 1.0, flags);
  for (int j = 0; j < judged.height; ++j)
    for (int i = 0; i < judged.width; ++i) {
      if (flags[static_cast<std::size_t>(i) + static_cast<std::size_t>(judged.width) * j] != PixelFlag::None) continue;
      bool differs = false;
      for (int k = 0; k < judged.planes && !differs; ++k) differs = judged.at(i, j, k) != exact.at(i, j, k);
      std::uint8_t* px = &img.rgb[3 * (static_cast<std::size_t>(i) +
                                       static_cast<std::size_t>(judged.width) * (judged.height - 1 - j))];
      if (differs) px[0] = 40, px[1] = 90, px[2] = 255;
    }
  return img;
}

}  // namespace

namespace {

// What one case renders, and how: the encoded series, its frame, and what the emulation simulates.
struct TimeVaryingRun {
  std::shared_ptr<const ref::TimeSeries> series;
  ref::TransferFunction tf;
  ref::TimeVaryingTextures tex;
  ref::PlaneFrame frame;
  const emu::PrecisionProfile* profile = nullptr;
  std::vector<emu::Effect> simulated;
  std::vector<emu::Departure> departures;
};

// What the steps measured, summed: every oracle reads it.
struct StepTally {
  std::size_t compared = 0, mismatched = 0, wrongColours = 0, samples = 0;
  int maxExactDiff = 0, maxIdealDiff = 0;
  double idealSumSq = 0.0;
  FetchCounts fetches;
  // Where the fetches came from: measured on GL in every step (fetchesOnGl), else the emulation's
  // where a profile exists, and why GL's were not measured.
  bool fetchesOnGl = true;
  std::string fetchesNotMeasured;
  std::size_t fetchesCompared = 0, fetchesDifferingFromEmulation = 0;  // GL's measured against the emulation's
  std::vector<std::size_t> departureChanges;
  std::string glNotRun;
  std::optional<ref::RgbaStack> firstGl, firstEmu, firstExact;  // the first step's, for the images
};

TimeVaryingRun prepareRun(CaseContext& ctx, const TimeVaryingScene& scene, CaseResult& result) {
  TimeVaryingRun run;
  const auto t0 = Clock::now();
  run.series = ctx.cached<ref::TimeSeries>("timevarying:" + seriesKey(scene),
                                           [&] { return std::make_shared<ref::TimeSeries>(makeSeries(scene)); });
  run.tf = ref::transferFunction(scene.transfer);
  run.tex = ref::encodeTimeVarying(*run.series, run.tf, scene.encoding);
  result.secondsReference += secondsSince(t0);
  run.frame = makeFrame(scene, run.tex.layout);
  const ref::EncodeStats& st = run.tex.stats;
  result.figures = {{"scene", toJson(scene)},
                    {"index_bytes", st.indexBytes},
                    {"refinement_bytes", st.refinementBytes},
                    {"ratio_against_4_bytes", st.ratioAgainst4Bytes()},
                    {"distinct_blocks", st.distinctBlocks},
                    {"hash_hits", st.hashHits},
                    {"hash_collisions", st.hashCollisions},
                    {"alpha_one_cells", st.alphaOneCells},
                    {"sparseness", ref::sparseness(*run.series)}};
  run.profile = ctx.profile();
  if (run.profile) {
    run.simulated = emu::TimeVaryingDecoderEmu(run.tex, scene.decoder, *run.profile).effects();
    run.simulated.push_back(emu::Effect::OutputUnorm8);
    if (scene.composite)
      for (emu::Effect e : emu::AlphaBlendEmu(*run.profile).effects()) run.simulated.push_back(e);
    for (emu::Effect e : run.simulated) result.effects.emplace_back(emu::effectId(e));
    run.departures = emu::departuresAmong(*run.profile, run.simulated);
  }
  return run;
}

// The GL decode or composite of one step; nothing (and why, in tally.glNotRun) where GL cannot run it.
std::optional<ref::RgbaStack> renderStepGl(CaseContext& ctx, const TimeVaryingRun& run, const TimeVaryingScene& scene,
                                           int step, StepTally& tally, CaseResult& result) {
  if (!ctx.gl()) {
    tally.glNotRun = "no GL context in this run";
    return std::nullopt;
  }
  if (!tally.glNotRun.empty()) return std::nullopt;
  try {
    const auto t0 = Clock::now();
    std::optional<ref::RgbaStack> gl =
        scene.composite
            ? gpu::compositeGl(*ctx.gl(), run.tex, scene.decoder, step, run.frame, {}, ctx.shaderOverride())
            : gpu::decodePlanesGl(*ctx.gl(), run.tex, scene.decoder, step, run.frame, {}, ctx.shaderOverride());
    result.secondsGl += secondsSince(t0);
    return gl;
  } catch (const gpu::GlUnsupported& e) {
    tally.glNotRun = e.what();
    return std::nullopt;
  }
}

// The right answer of one step: the exact colours, or for a composite the ideal composite rounded
// to codes (whose real-valued distance to GL goes into the tally).
ref::RgbaStack referenceOfStep(const TimeVaryingRun& run, const TimeVaryingScene& scene, int step,
                               const ref::RgbaStack* gl, StepTally& tally) {
  const ref::RgbaStack exact = ref::exactColours(*run.series, run.tf, step, run.frame);
  if (!scene.composite) return exact;
  const auto ideal = ref::idealComposite(exact, run.frame);
  ref::RgbaStack reference{run.frame.width, run.frame.height, 1, {}};
  for (const auto& c : ideal)
    reference.colours.push_back(
        {static_cast<std::uint8_t>(std::lround(c[0])), static_cast<std::uint8_t>(std::lround(c[1])),
         static_cast<std::uint8_t>(std::lround(c[2])), static_cast<std::uint8_t>(std::lround(c[3]))});
  if (gl)
    for (std::size_t i = 0; i < ideal.size(); ++i)
      for (int c = 0; c < 4; ++c) {
        const double d = gl->colours[i][c] - ideal[i][c];
        tally.idealSumSq += d * d;
        tally.maxIdealDiff = std::max(tally.maxIdealDiff, static_cast<int>(std::ceil(std::fabs(d) - 1e-9)));
      }
  return reference;
}

// How many of GL's samples each departure changes: GL against the emulation without it.
void countDepartures(CaseContext& ctx, const TimeVaryingRun& run, const TimeVaryingScene& scene, int step,
                     const ref::RgbaStack& gl, StepTally& tally) {
  for (std::size_t d = 0; d < run.departures.size(); ++d) {
    const emu::Departure& dep = run.departures[d];
    const ref::RgbaStack semantics =
        scene.composite
            ? emu::emulateComposite(run.tex, scene.decoder, step, run.frame, dep.semantics, ctx.threads(),
                                    dep.flushEachPass)
            : emu::emulateDecodePlanes(run.tex, scene.decoder, step, run.frame, dep.semantics, ctx.threads()).colours;
    for (std::size_t i = 0; i < gl.colours.size(); ++i)
      tally.departureChanges[d] += gl.colours[i] != semantics.colours[i];
  }
}

// GL against the emulation (exact oracle) and the judged colours against the right ones (ideal).
void compareStep(const ref::RgbaStack* gl, const ref::RgbaStack* emulated, const ref::RgbaStack& reference,
                 bool composite, StepTally& tally) {
  if (gl && emulated)
    for (std::size_t i = 0; i < gl->colours.size(); ++i) {
      ++tally.compared;
      if (gl->colours[i] != emulated->colours[i]) {
        ++tally.mismatched;
        tally.maxExactDiff =
            std::max(tally.maxExactDiff, largestChannelDifference(gl->colours[i], emulated->colours[i]).difference);
      }
    }
  const ref::RgbaStack* judged = gl ? gl : emulated;
  if (!judged) return;
  if (composite) {
    tally.samples += judged->colours.size();
    return;
  }
  for (std::size_t i = 0; i < judged->colours.size(); ++i) {
    ++tally.samples;
    if (judged->colours[i] != reference.colours[i]) {
      ++tally.wrongColours;
      tally.maxIdealDiff =
          std::max(tally.maxIdealDiff, largestChannelDifference(judged->colours[i], reference.colours[i]).difference);
    }
  }
}

// The texels GL fetched in one step, measured through the address textures; nothing (and why, in
// tally.fetchesNotMeasured) where they cannot be.
std::optional<ref::MeasuredFetches> measureFetchesOnGl(CaseContext& ctx, const TimeVaryingRun& run,
                                                       const TimeVaryingScene& scene, int step, StepTally& tally,
                                                       CaseResult& result) {
  if (!ctx.gl() || !tally.glNotRun.empty()) {
    tally.fetchesNotMeasured = !ctx.gl() ? "no GL context in this run" : "GL not run: " + tally.glNotRun;
    return std::nullopt;
  }
  try {
    const auto t0 = Clock::now();
    ref::MeasuredFetches m =
        gpu::measureFetchesGl(*ctx.gl(), run.tex, scene.decoder, step, run.frame, ctx.shaderOverride());
    result.secondsGl += secondsSince(t0);
    return m;
  } catch (const std::length_error& e) {
    tally.fetchesNotMeasured = e.what();
  } catch (const gpu::GlUnsupported& e) {
    tally.fetchesNotMeasured = e.what();
  }
  return std::nullopt;
}

// The step's fetches into the tally: GL's measured ones where there are, classified with the colours
// GL returned (a composite's: the fetched texels'), else the emulation's.
void tallyFetches(const TimeVaryingRun& run, const TimeVaryingScene& scene, int step,
                  const std::optional<ref::MeasuredFetches>& measured, const ref::RgbaStack* gl,
                  const emu::EmulatedDecode* decoded, StepTally& tally) {
  if (!measured) {
    tally.fetchesOnGl = false;
    if (decoded)
      tally.fetches.add(classifyFetches(run.tex, *run.series, run.tf, step, run.frame, emu::fetchesOf(*decoded),
                                        decoded->colours.colours));
    return;
  }
  const std::vector<ref::Rgba8> fetched = coloursOfFetches(run.tex, measured->fetches);
  const bool decodedOnGl = gl && !scene.composite;
  FetchCounts c = classifyFetches(run.tex, *run.series, run.tf, step, run.frame, measured->fetches,
                                  decodedOnGl ? gl->colours : fetched);
  c.unexplained =
      measured->unreadable + (decodedOnGl ? unexplainedColours(fetched, measured->fetches, gl->colours) : 0);
  tally.fetches.add(c);
  if (decoded) {
    tally.fetchesCompared += measured->fetches.size();
    tally.fetchesDifferingFromEmulation += differingFetches(measured->fetches, emu::fetchesOf(*decoded));
  }
}

// One time step through GL, the emulation and the reference, into the tally and the envelope.
void measureStep(CaseContext& ctx, const TimeVaryingRun& run, const TimeVaryingScene& scene, int step, StepTally& tally,
                 TimeVaryingEnvelopeOracle& envelope, std::vector<PixelFlag>& flags, CaseResult& result) {
  const std::optional<ref::RgbaStack> gl = renderStepGl(ctx, run, scene, step, tally, result);
  const std::optional<ref::MeasuredFetches> measured = measureFetchesOnGl(ctx, run, scene, step, tally, result);
  std::optional<ref::RgbaStack> emulated;
  std::optional<emu::EmulatedDecode> decoded;
  if (run.profile) {
    const auto t0 = Clock::now();
    decoded = emu::emulateDecodePlanes(run.tex, scene.decoder, step, run.frame, *run.profile, ctx.threads());
    emulated = scene.composite
                   ? emu::emulateComposite(run.tex, scene.decoder, step, run.frame, *run.profile, ctx.threads())
                   : decoded->colours;
    result.secondsEmulation += secondsSince(t0);
  }
  tallyFetches(run, scene, step, measured, gl ? &*gl : nullptr, decoded ? &*decoded : nullptr, tally);
  const auto t0 = Clock::now();
  const ref::RgbaStack reference = referenceOfStep(run, scene, step, gl ? &*gl : nullptr, tally);
  result.secondsReference += secondsSince(t0);
  if (gl) countDepartures(ctx, run, scene, step, *gl, tally);
  compareStep(gl ? &*gl : nullptr, emulated ? &*emulated : nullptr, reference, scene.composite, tally);
  envelope.add(step, gl ? &*gl : nullptr, emulated ? &*emulated : nullptr, reference, ctx.threads(),
               tally.firstExact ? nullptr : &flags);
  if (!tally.firstExact) {
    tally.firstExact = reference;
    tally.firstGl = gl;
    tally.firstEmu = emulated;
  }
}

OracleResult exactOracle(const StepTally& t, std::size_t steps, bool haveProfile) {
  if (!t.glNotRun.empty() || !haveProfile)
    return {"exact", Verdict::NotRun,
            !t.glNotRun.empty() ? "GL not run: " + t.glNotRun : "no precision profile for this driver",
            nlohmann::json::object()};
  const bool fetchesHold = t.fetchesDifferingFromEmulation == 0;
  return {"exact",
          t.mismatched || !fetchesHold ? Verdict::Fail : Verdict::Pass,
          std::to_string(t.mismatched) + " of " + std::to_string(t.compared) + " RGBA samples differ over " +
              std::to_string(steps) + " time step(s)" +
              (t.fetchesCompared
                   ? "; " + std::to_string(t.fetchesDifferingFromEmulation) + " of " +
                         std::to_string(t.fetchesCompared) + " texel fetches measured on GL differ from the emulation's"
                   : std::string()),
          {{"compared_samples", t.compared},
           {"mismatched_samples", t.mismatched},
           {"mismatched_pixels", t.mismatched},
           {"max_abs_diff_lsb", t.maxExactDiff},
           {"compared_fetches", t.fetchesCompared},
           {"fetches_differing_from_emulation", t.fetchesDifferingFromEmulation},
           {"steps", steps}},
          Judge::Exact};
}

// The fetch oracle: GL's fetches measured through the address textures (any driver, with or
// without a profile) against the exact addresses, and GL's colours against the exact decoder.
OracleResult fetchOracle(const StepTally& t, const TimeVaryingExpectation& expect, bool haveProfile) {
  const FetchCounts& f = t.fetches;
  if (!t.fetchesOnGl && !haveProfile)
    return {"fetch", Verdict::NotRun,
            "fetches not measured on GL (" + t.fetchesNotMeasured + ") and no profile to emulate them",
            nlohmann::json::object()};
  const bool clean = f.wrong() == 0 && f.wrongColour == 0;
  Verdict v = expect.everyFetchRight  ? (clean ? Verdict::Pass : Verdict::Fail)
              : expect.trapReproduced ? (f.wrongColour > 0 ? Verdict::Pass : Verdict::Fail)
                                      : Verdict::Info;
  if (f.unexplained > 0) v = Verdict::Fail;
  nlohmann::json figures = f.toJson();
  figures["measured_on"] = t.fetchesOnGl ? "gl" : "emulation";
  return {"fetch", v,
          std::string(t.fetchesOnGl ? "measured on GL: "
                                    : "emulated (not measured on GL: " + t.fetchesNotMeasured + "): ") +
              std::to_string(f.wrong()) + " of " + std::to_string(f.samples) + " fetches wrong (" +
              std::to_string(f.wrongBlock) + " wrong block, " + std::to_string(f.wrongVoxel) + " wrong voxel; " +
              std::to_string(f.atCoordinateOne) + " at 1.0, " + std::to_string(f.onBlockFace) + " on block faces, " +
              std::to_string(f.onVoxelFace) + " on voxel faces, " + std::to_string(f.inside) + " inside); " +
              std::to_string(f.wrongColour) + " wrong colours" +
              (expect.everyFetchRight  ? " (must be 0)"
               : expect.trapReproduced ? " (the paper's trap must show)"
                                       : "") +
              (f.unexplained ? "; " + std::to_string(f.unexplained) +
                                   " samples where GL's colour is not the texel its fetch measured"
                             : std::string()),
          figures, t.fetchesOnGl ? Judge::Fetch : Judge::None};
}

OracleResult idealOracle(const StepTally& t, bool composite) {
  if (composite) {
    const double rmse = t.samples ? std::sqrt(t.idealSumSq / (4.0 * static_cast<double>(t.samples))) : 0.0;
    return {"ideal",
            Verdict::Info,
            "composited image vs the exact colours composited in real arithmetic: max " +
                std::to_string(t.maxIdealDiff) + " LSB, RMSE " + std::to_string(rmse) + " LSB",
            {{"max_abs_diff_lsb", t.maxIdealDiff}, {"rmse", rmse}, {"pixels", t.samples}}};
  }
  return {"ideal",
          Verdict::Info,
          std::to_string(t.wrongColours) + " of " + std::to_string(t.samples) +
              " samples decode another colour than the exact decoder" +
              (t.wrongColours ? " (max channel difference " + std::to_string(t.maxIdealDiff) + ")" : ""),
          {{"wrong_colours", t.wrongColours},
           {"samples", t.samples},
           {"max_abs_diff_lsb", t.maxIdealDiff},
           {"rmse", nullptr}}};
}

// The first step's images: GL, emulated, the right answer, and the error mask.
void writeImages(CaseContext& ctx, CaseResult& result, const StepTally& t, bool composite,
                 const std::vector<PixelFlag>& flags) {
  const int plane = composite ? 0 : t.firstExact->planes / 2;
  io::ensureDirectory(ctx.outDir() / "images");
  auto write = [&](const ref::RgbaStack& s, const std::string& kind, std::string& slot) {
    slot = caseImageName(result.id, kind);
    io::writePng(ctx.outDir() / slot, rgbPreview(s, plane));
  };
  if (t.firstGl) write(*t.firstGl, "rendered", result.images.rendered);
  if (t.firstEmu) write(*t.firstEmu, "emulated", result.images.emulated);
  write(*t.firstExact, "reference", result.images.reference);
  if (t.firstGl || t.firstEmu) {
    result.images.errorMask = caseImageName(result.id, "error_mask");
    io::writePng(ctx.outDir() / result.images.errorMask,
                 maskPreview(t.firstGl ? *t.firstGl : *t.firstEmu, *t.firstExact, plane, flags));
  }
}

}  // namespace

CaseResult judgeTimeVarying(CaseContext& ctx, const std::string& id, const std::string& description,
                            const TimeVaryingScene& scene, const TimeVaryingExpectation& expect) {
  CaseResult result;
  result.id = id;
  result.system = "timevarying";
  result.description = description;
  const TimeVaryingRun run = prepareRun(ctx, scene, result);
  StepTally tally;
  tally.departureChanges.assign(run.departures.size(), 0);
  TimeVaryingEnvelopeOracle envelope(run.tex, scene.decoder, run.frame, scene.composite, ctx.measured());
  std::vector<PixelFlag> flags(static_cast<std::size_t>(run.frame.width) * run.frame.height, PixelFlag::None);
  const std::vector<int> steps = stepsOf(scene);
  for (int step : steps) measureStep(ctx, run, scene, step, tally, envelope, flags, result);

  for (std::size_t d = 0; d < run.departures.size(); ++d)
    result.findings.push_back({std::string(run.departures[d].id),
                               std::string(run.departures[d].description),
                               {{"samples_changed", tally.departureChanges[d]}, {"pixels_compared", tally.samples}}});
  result.worstPixels = envelope.worstPixels();
  result.oracles = {exactOracle(tally, steps.size(), run.profile != nullptr), envelope.result(),
                    fetchOracle(tally, expect, run.profile != nullptr), idealOracle(tally, scene.composite)};
  concludeFromOracles(result);
  if (!tally.glNotRun.empty() && ctx.gl()) {
    result.status = Status::Skip;
    result.message = tally.glNotRun;
  }
  if ((ctx.writeAllImages() || result.status == Status::Fail || result.status == Status::Warn) && tally.firstExact)
    writeImages(ctx, result, tally, scene.composite, flags);
  return result;
}

Case timeVaryingCase(std::string id, std::string description, TimeVaryingScene scene,
                     TimeVaryingExpectation expectation) {
  Case c;
  c.id = id;
  c.system = "timevarying";
  c.description = description;
  c.run = [id, description, scene, expectation](CaseContext& ctx) {
    return judgeTimeVarying(ctx, id, description, scene, expectation);
  };
  c.scene = toJson(scene);
  return c;
}

}  // namespace voxref::conf
