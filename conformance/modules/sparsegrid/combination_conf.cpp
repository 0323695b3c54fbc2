#include "conformance/modules/sparsegrid/combination_conf.h"
#include "conformance/framework/stopwatch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "conformance/framework/compare.h"
#include "conformance/framework/report/case_images.h"
#include "conformance/framework/report/worst_samples.h"
#include "conformance/io/atomic_file.h"
#include "conformance/modules/sparsegrid/prepared_scene.h"
#include "emulation/combination_envelope.h"
#include "gpu/combination_gl.h"
#include "gpu/gl_error.h"
#include "reference/common/parallel.h"

namespace voxref::conf {
namespace {

const ref::CodePlanes& envelopeJudged(const CombinationPlanes& r) { return r.gl ? *r.gl : r.emulated->planes; }

// Also returns, per sample, how far the judged value lies outside the pass envelope (0 inside).
std::vector<double> judgeEnvelope(CombinationPlanes& r, const emu::CombinationEnvelope& envelope, int threads) {
  const ref::CodePlanes& judged = envelopeJudged(r);
  r.envelopeJudged = r.gl ? "gl" : "emulation";
  r.envelopeThreshold = envelope.colourThreshold();
  r.envelopeBasis = envelope.basis();
  r.envelopeSpecStages = envelope.specStages();
  r.envelopeUvwBits = {envelope.passPrecision().uvwBits, envelope.warningPrecision().uvwBits};
  r.envelope.assign(judged.codes.size(), 0);
  std::vector<double> excess(judged.codes.size(), 0.0);
  const int w = r.frame.width, h = r.frame.height;
  std::vector<double> widest(static_cast<std::size_t>(r.frame.planes), 0.0);
  ref::parallelFor(r.frame.planes, threads, [&](int k) {
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const std::size_t idx =
            static_cast<std::size_t>(i) + static_cast<std::size_t>(w) * (j + static_cast<std::size_t>(h) * k);
        const double v = ref::decodeFramebufferCode(judged.format, judged.codes[idx]);
        const emu::Interval pass = envelope.at(i, j, k, envelope.passPrecision());
        widest[static_cast<std::size_t>(k)] = std::max(widest[static_cast<std::size_t>(k)], pass.hi - pass.lo);
        if (pass.contains(v)) continue;
        excess[idx] = v < pass.lo ? pass.lo - v : v - pass.hi;
        r.envelope[idx] = envelope.at(i, j, k, envelope.warningPrecision()).contains(v) ? 1 : 2;
      }
  });
  r.envelopeWidest = widest.empty() ? 0.0 : *std::max_element(widest.begin(), widest.end());
  for (std::size_t idx = 0; idx < r.envelope.size(); ++idx) {
    if (r.envelope[idx] == 1) ++r.envelopeWarn;
    if (r.envelope[idx] != 2) continue;
    if (r.envelopeFail++ >= 20) continue;
    const int i = static_cast<int>(idx % w), j = static_cast<int>((idx / w) % h),
              k = static_cast<int>(idx / (static_cast<std::size_t>(w) * h));
    const emu::Interval pass = envelope.at(i, j, k, envelope.passPrecision());
    r.envelopeFailures.push_back({{"sample", {i, j, k}},
                                  {"value", ref::decodeFramebufferCode(judged.format, judged.codes[idx])},
                                  {"allowed", {pass.lo, pass.hi}}});
  }
  return excess;
}

// CombinationPlanes::worst; `excess` from judgeEnvelope (empty when no envelope ran).
void pickWorstSamples(CombinationPlanes& r, const emu::CombinationEnvelope* envelope,
                      const std::vector<double>& excess) {
  const std::size_t n = r.reference.values.size();
  std::vector<std::vector<std::size_t>> wrong;
  if (r.gl && r.emulated) {
    const CodeComparison c = compareCodes(*r.gl, r.emulated->planes, &r.emulated->unmodelled);
    std::vector<double> distance(n, 0.0);
    for (std::size_t s = 0; s < c.mask.size(); ++s)
      if (c.mask[s])
        distance[s] = static_cast<double>(codeDistance(r.gl->format, r.gl->codes[s], r.emulated->planes.codes[s]));
    wrong.push_back(largestScores(distance, kMaxWorstPixels));
  }
  std::vector<double> failing(n, 0.0), warned(n, 0.0);
  for (std::size_t s = 0; s < excess.size(); ++s) (r.envelope[s] == 2 ? failing : warned)[s] = excess[s];
  wrong.push_back(largestScores(failing, kMaxWorstPixels));
  std::vector<std::size_t> chosen = interleaveRanked(wrong, kMaxWorstPixels);
  if (chosen.size() < kMaxWorstPixels)
    for (std::size_t s : largestScores(warned, kMaxWorstPixels))
      if (chosen.size() < kMaxWorstPixels && std::find(chosen.begin(), chosen.end(), s) == chosen.end())
        chosen.push_back(s);

  const ref::CodePlanes* gl = r.gl ? &*r.gl : nullptr;
  const ref::CodePlanes* emulated = r.emulated ? &r.emulated->planes : nullptr;
  auto value = [&](const ref::CodePlanes* p, std::size_t s) {
    return p ? r.readbackScale * ref::decodeFramebufferCode(p->format, p->codes[s]) : std::nan("");
  };
  if (chosen.empty()) {  // nothing wrong: the largest distances from the reference
    std::vector<double> error(n, 0.0);
    if (const ref::CodePlanes* judged = gl ? gl : emulated)
      for (std::size_t s = 0; s < n; ++s) error[s] = std::fabs(value(judged, s) - r.reference.values[s]);
    chosen = largestScores(error, kMaxWorstPixels);
  }
  const std::size_t w = static_cast<std::size_t>(r.frame.width), h = static_cast<std::size_t>(r.frame.height);
  r.worst.clear();
  for (std::size_t s : chosen) {
    PixelValues p;
    p.x = static_cast<int>(s % w), p.y = static_cast<int>((s / w) % h), p.k = static_cast<int>(s / (w * h));
    const bool unmodelled = r.emulated && s < r.emulated->unmodelled.size() && r.emulated->unmodelled[s];
    const bool mismatch = gl && emulated && gl->codes[s] != emulated->codes[s] && !unmodelled;
    p.oracle = mismatch ? "exact" : s < r.envelope.size() && r.envelope[s] != 0 ? "envelope" : "ideal";
    p.gl = value(gl, s);
    p.emulated = value(emulated, s);
    p.reference = r.reference.values[s];
    if (envelope) {
      const emu::Interval pass = envelope->at(p.x, p.y, p.k, envelope->passPrecision());
      p.allowed = std::make_pair(r.readbackScale * pass.lo, r.readbackScale * pass.hi);
    }
    r.worst.push_back(p);
  }
}

// Runs the semantics of every departure of the profile and records, per departure, the samples
// where the driver's output differs from those semantics; envelope failures and warnings are
// attributed to the departures that change their sample.
void findDepartures(CombinationPlanes& r, const ref::CombinationTextures& textures,
                    const emu::PrecisionProfile& profile, int threads) {
  std::vector<std::uint8_t> explained(r.envelope.size(), 0);
  for (const emu::Departure& d : emu::departuresAmong(profile, r.simulated)) {
    const emu::EmulatedPlanes semantics =
        emu::emulateCombination(textures, r.frame, r.scene.sampler, r.scene.framebuffer, d.semantics,
                                {d.flushEachPass || r.scene.flushEachPass, threads});
    const CodeComparison c = compareCodes(*r.gl, semantics.planes, &semantics.unmodelled);
    std::size_t fails = 0, warns = 0;
    for (std::size_t s = 0; s < c.mask.size() && s < r.envelope.size(); ++s) {
      if (!c.mask[s]) continue;
      explained[s] = 1;
      fails += r.envelope[s] == 2;
      warns += r.envelope[s] == 1;
    }
    r.departures.push_back({std::string(d.id),
                            std::string(d.description),
                            {{"samples_changed", c.mismatched},
                             {"samples_compared", c.compared},
                             {"max_abs_diff_lsb", c.maxDistance},
                             {"envelope_failures_at_changed_samples", fails},
                             {"envelope_warnings_at_changed_samples", warns}}});
  }
  r.unexplainedFail = r.unexplainedWarn = 0;
  for (std::size_t s = 0; s < r.envelope.size(); ++s) {
    if (explained[s]) continue;
    r.unexplainedFail += r.envelope[s] == 2;
    r.unexplainedWarn += r.envelope[s] == 1;
  }
}

}  // namespace

std::shared_ptr<CombinationPlanes> computeCombinationPlanes(CaseContext& ctx, const SparseGridScene& scene) {
  auto r = std::make_shared<CombinationPlanes>();
  r->scene = scene;
  const int threads = ctx.threads();
  auto t0 = Clock::now();
  const PreparedScene prepared = prepareScene(scene);
  r->frame = prepared.frame;
  r->reference = referencePlanes(prepared, threads);
  r->secondsReference = secondsSince(t0);
  const ref::CombinationTextures& textures = prepared.textures;
  r->gridCount = static_cast<int>(prepared.combination->grids().size());
  r->positiveCount = prepared.combination->positiveCount();
  r->passCount = textures.passes.size();
  r->textureBytes = ref::textureBytes(textures);
  r->brickedGrids = ref::brickedGridCount(textures);
  r->readbackScale = textures.readbackScale;

  const emu::PrecisionProfile* profile = ctx.profile();
  if (!profile) {
    r->emulationNotRun = "no precision profile for this driver (judged by the envelope oracle alone)";
  } else {
    try {
      const emu::CombinationEmuOptions options{scene.flushEachPass, threads};
      r->simulated = emu::combinationEffects(textures, scene.sampler, scene.framebuffer, *profile, options,
                                             r->frame.width, r->frame.height);
      for (emu::Effect e : r->simulated) r->effects.emplace_back(emu::effectId(e));
      t0 = Clock::now();
      r->emulated = emu::emulateCombination(textures, r->frame, scene.sampler, scene.framebuffer, *profile, options);
      r->secondsEmulation = secondsSince(t0);
    } catch (const std::invalid_argument& e) {
      r->emulationNotRun = e.what();
    }
  }

  if (!ref::existsInGl(scene.framebuffer)) {
    r->glNotRun = "GL has no " + std::string(ref::name(scene.framebuffer)) + " colour buffer (emulated only)";
  } else if (!ctx.gl()) {
    r->glNotRun = "no GL context in this run";
  } else {
    try {
      t0 = Clock::now();
      r->gl = gpu::renderCombinationGl(*ctx.gl(), textures, r->frame, scene.sampler, scene.framebuffer,
                                       {scene.flushEachPass, ctx.shaderOverride()});
      r->secondsGl = secondsSince(t0);
    } catch (const gpu::GlUnsupported& e) {
      r->glNotRun = e.what();
    }
  }

  std::optional<emu::CombinationEnvelope> envelope;
  std::vector<double> excess;
  if (r->gl || r->emulated) {
    envelope.emplace(textures, r->frame, scene.sampler, envelopeJudged(*r).format, ctx.measured());
    excess = judgeEnvelope(*r, *envelope, threads);
  }
  if (r->gl && profile) findDepartures(*r, textures, *profile, threads);
  pickWorstSamples(*r, envelope ? &*envelope : nullptr, excess);
  return r;
}

namespace {

OracleResult exactOracle(const CombinationPlanes& r, const ref::Image* glImage, const ref::Image* emuImage,
                         std::vector<PixelFlag>& flags) {
  OracleResult o{"exact", Verdict::NotRun, "", nlohmann::json::object()};
  if (!r.gl || !r.emulated) {
    o.summary = !r.gl ? "GL not run: " + r.glNotRun : "emulation not run: " + r.emulationNotRun;
    return o;
  }
  o.judges = Judge::Exact;
  const CodeComparison c = compareCodes(*r.gl, r.emulated->planes, &r.emulated->unmodelled);
  const ImageComparison img = compareImages(*glImage, *emuImage);
  const bool unorm = ref::unormBits(r.gl->format) != 0;
  o.figures = {{"compared_samples", c.compared},     {"excluded_samples", c.excluded},
               {"mismatched_samples", c.mismatched}, {"max_abs_diff_lsb", c.maxDistance},
               {"diff_unit", unorm ? "lsb" : "ulp"}, {"mismatched_pixels", img.mismatchedPixels}};
  const int w = r.frame.width, h = r.frame.height;
  if (c.mismatched) {
    const std::size_t idx = c.firstMismatch;
    o.figures["first_mismatch"] = {{"sample", {idx % w, (idx / w) % h, idx / (static_cast<std::size_t>(w) * h)}},
                                   {"gl_code", r.gl->codes[idx]},
                                   {"emulated_code", r.emulated->planes.codes[idx]}};
    for (std::size_t s = 0; s < c.mask.size(); ++s)
      if (c.mask[s]) flags[s % (static_cast<std::size_t>(w) * h)] = PixelFlag::ExactMismatch;
  }
  if (c.mismatched) {
    o.verdict = Verdict::Fail;
    o.summary = std::to_string(c.mismatched) + " of " + std::to_string(c.compared) + " samples differ (max " +
                std::to_string(c.maxDistance) + (unorm ? " LSB)" : " ULP)");
  } else if (c.excluded) {
    o.verdict = Verdict::Warn;
    o.summary = "0 of " + std::to_string(c.compared) + " samples differ; " + std::to_string(c.excluded) +
                " not judged (the model cannot know their value: stale tile-cache data)";
  } else {
    o.verdict = Verdict::Pass;
    o.summary = "0 of " + std::to_string(c.compared) + " samples differ, 0 of " + std::to_string(w * h) + " pixels";
  }
  return o;
}

OracleResult envelopeOracle(const CombinationPlanes& r, std::vector<PixelFlag>& flags) {
  OracleResult o{"envelope", Verdict::NotRun, "", nlohmann::json::object()};
  if (r.envelope.empty()) {
    o.summary = "nothing to judge: " + r.glNotRun + "; " + r.emulationNotRun;
    return o;
  }
  const std::size_t n = r.envelope.size();
  o.figures = {{"judged", r.envelopeJudged},
               {"samples", n},
               {"pass", n - r.envelopeWarn - r.envelopeFail},
               {"quality_warning", r.envelopeWarn},
               {"fail", r.envelopeFail},
               {"colour_threshold", r.envelopeThreshold},
               {"basis", r.envelopeBasis},
               {"precision",
                {{"coord_bits", emu::kEnvelopePass.coordBits},
                 {"uvw_bits_pass", r.envelopeUvwBits.first},
                 {"uvw_bits_warning", r.envelopeUvwBits.second},
                 {"division_ulps", emu::kEnvelopePass.divisionUlps}}},
               {"failures", r.envelopeFailures}};
  // How much the envelope can tell: its widest interval against the spread of the true values.
  // Many passes into a low-precision target may allow more than the signal itself (issue 6 note).
  const auto [lo, hi] = std::minmax_element(r.reference.values.begin(), r.reference.values.end());
  const double spread = r.reference.values.empty() ? 0.0 : *hi - *lo;
  o.figures["widest_allowed"] = r.envelopeWidest;
  o.figures["reference_spread"] = spread;
  o.figures["blind"] = r.envelopeWidest >= spread;
  o.figures["spec_stages"] = r.envelopeSpecStages;
  // It judges GL only where GL ran and its intervals can tell GL's output from a constant.
  if (r.envelopeJudged == "gl" && r.envelopeWidest < spread) o.judges = Judge::Envelope;
  if (!r.departures.empty()) {
    o.figures["unexplained_failures"] = r.unexplainedFail;
    o.figures["unexplained_warnings"] = r.unexplainedWarn;
  }
  const std::size_t plane = static_cast<std::size_t>(r.frame.width) * r.frame.height;
  for (std::size_t s = 0; s < n; ++s) {
    PixelFlag& f = flags[s % plane];
    if (r.envelope[s] == 2 && f != PixelFlag::ExactMismatch) f = PixelFlag::EnvelopeFail;
    if (r.envelope[s] == 1 && f == PixelFlag::None) f = PixelFlag::EnvelopeWarn;
  }
  const std::string who = r.envelopeJudged == "gl" ? "GL" : "emulated";
  if (r.envelopeFail) {
    o.verdict = Verdict::Fail;
    const auto& first = r.envelopeFailures.front();
    o.summary = std::to_string(r.envelopeFail) + " of " + std::to_string(n) + " " + who +
                " samples outside the envelope; first " + first["sample"].dump() + " = " + first["value"].dump() +
                " not in " + first["allowed"].dump();
    if (!r.departures.empty())
      o.summary += "; " + std::to_string(r.envelopeFail - r.unexplainedFail) +
                   " at samples a named departure of the driver changes";
  } else if (r.envelopeWarn) {
    o.verdict = Verdict::Warn;
    o.summary = std::to_string(r.envelopeWarn) + " of " + std::to_string(n) + " " + who +
                " samples only inside the relaxed (quality warning) envelope";
  } else {
    o.verdict = Verdict::Pass;
    o.summary = "all " + std::to_string(n) + " " + who + " samples inside the envelope";
  }
  if (r.envelopeWidest >= spread) {
    char note[200];
    std::snprintf(
        note, sizeof note,
        "; blind here: its widest interval (%.4g) spans the reference's whole spread (%.4g), so only the exact oracle "
        "can tell this scene's output from a constant",
        r.envelopeWidest, spread);
    o.summary += note;
    // Why no tighter bound: the stages still at the spec's rules, or that every stage is measured.
    o.summary +=
        "; no tighter bound derived: " +
        (r.envelopeSpecStages.empty() ? std::string("every stage already uses a measured rule") : r.envelopeSpecStages);
  }
  return o;
}

OracleResult idealOracle(const CombinationPlanes& r, const ref::SampleStack& judged, const ref::Image& image,
                         const ref::Image& referenceImage, const std::string& who) {
  OracleResult o{"ideal", Verdict::Info, "", nlohmann::json::object()};
  const ErrorFigures planes = compareValues(judged.values, r.reference.values, 1.0);
  const double peak = *std::max_element(referenceImage.pixels.begin(), referenceImage.pixels.end());
  const ErrorFigures img = compareValues(image.pixels, referenceImage.pixels, peak > 0.0 ? peak : 1.0);
  std::size_t negative = 0;
  for (double v : r.reference.values) negative += v < 0.0;
  o.figures = {{"judged", who},
               {"planes", {{"max_abs_error", planes.maxAbs}, {"rmse", planes.rmse}, {"psnr_db", planes.psnrDb}}},
               {"image", {{"max_abs_error", img.maxAbs}, {"rmse", img.rmse}, {"psnr_db", img.psnrDb}}},
               {"rmse", planes.rmse},
               {"reference_negative_samples", negative}};
  const int bits = ref::unormBits(r.scene.framebuffer);
  if (bits) {
    const double lsb = r.readbackScale / (std::ldexp(1.0, bits) - 1.0);
    o.figures["planes"]["max_abs_error_lsb"] = planes.maxAbs / lsb;
    o.figures["max_abs_diff_lsb"] = planes.maxAbs / lsb;
  }
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s planes vs double reference: max %.3g, RMSE %.3g, PSNR %.1f dB", who.c_str(),
                planes.maxAbs, planes.rmse, planes.psnrDb);
  o.summary = buf;
  return o;
}

void writeImages(CaseContext& ctx, CaseResult& result, const ref::Image* glImage, const ref::Image* emuImage,
                 const ref::Image& refImage, const std::vector<PixelFlag>& flags) {
  const double peak = *std::max_element(refImage.pixels.begin(), refImage.pixels.end());
  const double scale = peak > 0.0 ? 1.0 / peak : 1.0;
  io::ensureDirectory(ctx.outDir() / "images");
  auto write = [&](const ref::Image& img, const std::string& kind, std::string& slot) {
    slot = caseImageName(result.id, kind);
    io::writePng(ctx.outDir() / slot, grayPreview(img, scale));
  };
  if (glImage) write(*glImage, "rendered", result.images.rendered);
  if (emuImage) write(*emuImage, "emulated", result.images.emulated);
  write(refImage, "reference", result.images.reference);
  result.images.errorMask = caseImageName(result.id, "error_mask");
  io::writePng(ctx.outDir() / result.images.errorMask, errorMaskPreview(glImage    ? *glImage
                                                                        : emuImage ? *emuImage
                                                                                   : refImage,
                                                                        scale, flags));
}

}  // namespace

CaseResult judgeCombination(CaseContext& ctx, const std::string& id, const std::string& description,
                            const SparseGridScene& scene) {
  const auto r = ctx.cached<CombinationPlanes>(planeKey(scene), [&] { return computeCombinationPlanes(ctx, scene); });
  CaseResult result;
  result.id = id;
  result.system = "sparsegrid";
  result.description = description;
  result.effects = r->effects;
  result.findings = r->departures;
  result.worstPixels = r->worst;
  result.secondsGl = r->secondsGl;
  result.secondsEmulation = r->secondsEmulation;
  result.secondsReference = r->secondsReference;
  result.figures = {{"level", scene.grid.level},
                    {"boundary", scene.grid.boundary},
                    {"grids", r->gridCount},
                    {"positive_grids", r->positiveCount},
                    {"passes", r->passCount},
                    {"texture_bytes", r->textureBytes},
                    {"bricked_grids", r->brickedGrids},
                    {"samples", r->reference.values.size()},
                    {"scene", toJson(scene)}};

  const ref::Image refImage = ref::shadePlanes(r->reference, r->frame, scene.shading);
  std::optional<ref::Image> glImage, emuImage;
  std::optional<ref::SampleStack> glStack, emuStack;
  if (r->gl) {
    glStack = ref::toSampleStack(*r->gl, r->readbackScale);
    glImage = ref::shadePlanes(*glStack, r->frame, scene.shading);
  }
  if (r->emulated) {
    emuStack = ref::toSampleStack(r->emulated->planes, r->readbackScale);
    emuImage = ref::shadePlanes(*emuStack, r->frame, scene.shading);
  }

  std::vector<PixelFlag> flags(static_cast<std::size_t>(r->frame.width) * r->frame.height, PixelFlag::None);
  result.oracles.push_back(exactOracle(*r, glImage ? &*glImage : nullptr, emuImage ? &*emuImage : nullptr, flags));
  result.oracles.push_back(envelopeOracle(*r, flags));
  if (glStack)
    result.oracles.push_back(idealOracle(*r, *glStack, *glImage, refImage, "GL"));
  else if (emuStack)
    result.oracles.push_back(idealOracle(*r, *emuStack, *emuImage, refImage, "emulated"));

  concludeFromOracles(result);
  if (!r->gl && ref::existsInGl(scene.framebuffer)) {
    // GL could not run what the case is about: a skip with the reason, never a pass.
    result.status = Status::Skip;
    result.message = r->glNotRun;
  }
  if (ctx.writeAllImages() || result.status == Status::Fail || result.status == Status::Warn)
    writeImages(ctx, result, glImage ? &*glImage : nullptr, emuImage ? &*emuImage : nullptr, refImage, flags);
  return result;
}

Case combinationCase(std::string id, std::string description, SparseGridScene scene) {
  Case c;
  c.id = id;
  c.system = "sparsegrid";
  c.description = description;
  c.run = [id, description, scene](CaseContext& ctx) { return judgeCombination(ctx, id, description, scene); };
  c.scene = toJson(scene);
  return c;
}

}  // namespace voxref::conf
