#include "conformance/modules/timevarying/timevarying_envelope_conf.h"

#include <algorithm>
#include <cmath>

#include "conformance/framework/compare.h"
#include "conformance/framework/report/worst_samples.h"

namespace voxref::conf {
namespace {

constexpr std::size_t kListedFailures = 20;
constexpr const char* kChannels = "rgba";

}  // namespace

TimeVaryingEnvelopeOracle::TimeVaryingEnvelopeOracle(const ref::TimeVaryingTextures& textures,
                                                     ref::DecoderVariant decoder, const ref::PlaneFrame& frame,
                                                     bool composite, const emu::MeasuredArithmetic& measured)
    : envelope_(textures, decoder, measured), frame_(&frame), composite_(composite) {}

PixelValues TimeVaryingEnvelopeOracle::valuesAt(std::size_t idx, int channel, const ref::RgbaStack* gl,
                                                const ref::RgbaStack* emulated, const ref::RgbaStack& reference) const {
  const std::size_t w = static_cast<std::size_t>(frame_->width), h = static_cast<std::size_t>(frame_->height);
  PixelValues p;
  p.x = static_cast<int>(idx % w), p.y = static_cast<int>((idx / w) % h), p.k = static_cast<int>(idx / (w * h));
  p.gl = gl ? gl->colours[idx][channel] : std::nan("");
  p.emulated = emulated ? emulated->colours[idx][channel] : std::nan("");
  p.reference = reference.colours[idx][channel];
  return p;
}

void TimeVaryingEnvelopeOracle::keep(int kind, int step, const std::vector<double>& scores, const ref::RgbaStack* gl,
                                     const ref::RgbaStack* emulated, const ref::RgbaStack& reference,
                                     const std::vector<int>& channel) {
  static const char* kOracle[] = {"exact", "envelope", "envelope", "ideal"};
  for (std::size_t idx : largestScores(scores, kMaxWorstPixels)) {
    PixelValues p = valuesAt(idx, channel[idx], gl, emulated, reference);
    p.oracle = kOracle[kind];
    // The allowed codes of the shown channel in the allowed candidate nearest to the judged colour.
    const ref::RgbaStack& judged = gl ? *gl : *emulated;
    const emu::AllowedColours allowed =
        composite_ ? envelope_.composited(step, *frame_, p.x, p.y, emu::kEnvelopePass)
                   : envelope_.decoded(step, frame_->sample(p.x, p.y, p.k), emu::kEnvelopePass);
    const emu::Interval a = allowed.boxes[allowed.miss(judged.colours[idx]).box][channel[idx]];
    p.allowed = std::make_pair(a.lo, a.hi);
    candidates_.push_back({scores[idx], kind, p});
  }
}

void TimeVaryingEnvelopeOracle::add(int step, const ref::RgbaStack* gl, const ref::RgbaStack* emulated,
                                    const ref::RgbaStack& reference, int threads, std::vector<PixelFlag>* flags) {
  const ref::RgbaStack* judged = gl ? gl : emulated;
  if (!judged) return;
  judged_ = gl ? "gl" : "emulation";
  std::vector<std::uint8_t> widths;
  const std::vector<std::uint8_t> tiers =
      emu::envelopeTiers(envelope_, step, *frame_, composite_, *judged, threads, &widths);
  const std::size_t n = tiers.size(), plane = static_cast<std::size_t>(frame_->width) * frame_->height;
  samples_ += n;
  std::vector<double> exactScore(n, 0.0), failScore(n, 0.0), warnScore(n, 0.0), idealScore(n, 0.0);
  std::vector<int> channel(n, 0);
  for (std::size_t s = 0; s < n; ++s) {
    if (widths[s] > widestCodes_) {
      widestCodes_ = widths[s];
      widestAt_ = {{"sample", {s % frame_->width, (s / frame_->width) % frame_->height, s / plane}}, {"step", step}};
    }
    if (gl && emulated && gl->colours[s] != emulated->colours[s]) {
      const auto [d, c] = largestChannelDifference(gl->colours[s], emulated->colours[s]);
      exactScore[s] = d, channel[s] = c;
      if (flags) (*flags)[s % plane] = PixelFlag::ExactMismatch;
    }
    if (judged->colours[s] != reference.colours[s])
      idealScore[s] = largestChannelDifference(judged->colours[s], reference.colours[s]).difference;
    if (tiers[s] == 0) continue;
    const emu::AllowedColours allowed =
        composite_ ? envelope_.composited(step, *frame_, static_cast<int>(s % frame_->width),
                                          static_cast<int>((s / frame_->width) % frame_->height), emu::kEnvelopePass)
                   : envelope_.decoded(step,
                                       frame_->sample(static_cast<int>(s % frame_->width),
                                                      static_cast<int>((s / frame_->width) % frame_->height),
                                                      static_cast<int>(s / plane)),
                                       emu::kEnvelopePass);
    const emu::AllowedColours::Miss m = allowed.miss(judged->colours[s]);
    if (exactScore[s] == 0.0) channel[s] = m.channel;
    (tiers[s] == 2 ? failScore : warnScore)[s] = m.codes;
    if (flags && (*flags)[s % plane] != PixelFlag::ExactMismatch)
      (*flags)[s % plane] =
          tiers[s] == 2 ? PixelFlag::EnvelopeFail : std::max((*flags)[s % plane], PixelFlag::EnvelopeWarn);
    if (tiers[s] == 1) {
      ++warnings_;
      continue;
    }
    if (failures_++ >= kListedFailures) continue;
    const ref::Rgba8& v = judged->colours[s];
    failureList_.push_back({{"sample", {s % frame_->width, (s / frame_->width) % frame_->height, s / plane}},
                            {"step", step},
                            {"rgba", {v[0], v[1], v[2], v[3]}},
                            {"channel", std::string(1, kChannels[m.channel])},
                            {"value", v[m.channel]},
                            {"allowed", {static_cast<int>(m.allowed.lo), static_cast<int>(m.allowed.hi)}},
                            {"candidates", allowed.boxes.size()}});
  }
  for (std::size_t s = 0; s < n; ++s)
    if (idealScore[s] > 0.0 && exactScore[s] == 0.0 && failScore[s] == 0.0 && warnScore[s] == 0.0)
      channel[s] = largestChannelDifference(judged->colours[s], reference.colours[s]).channel;
  keep(0, step, exactScore, gl, emulated, reference, channel);
  keep(1, step, failScore, gl, emulated, reference, channel);
  keep(2, step, warnScore, gl, emulated, reference, channel);
  keep(3, step, idealScore, gl, emulated, reference, channel);
}

OracleResult TimeVaryingEnvelopeOracle::result() const {
  OracleResult o{"envelope", Verdict::NotRun, "", nlohmann::json::object()};
  if (judged_.empty()) {
    o.summary = "nothing to judge: neither GL nor the emulation ran";
    return o;
  }
  o.figures = {{"judged", judged_},
               {"samples", samples_},
               {"pass", samples_ - warnings_ - failures_},
               {"quality_warning", warnings_},
               {"fail", failures_},
               {"unit", "rgba8 code"},
               {"widest_allowed_codes", widestCodes_},  // per-channel hull width over the candidates
               {"widest_at", widestAt_},
               {"basis", composite_ ? envelope_.basis() : std::string("spec")},
               {"union", composite_ ? "per-channel hull of the candidates, propagated through the blend"
                                    : "union of per-candidate RGBA boxes"},
               {"precision",
                {{"coord_bits", emu::kEnvelopePass.coordBits},
                 {"uvw_bits_pass", emu::kEnvelopePass.uvwBits},
                 {"uvw_bits_warning", emu::kEnvelopeQualityWarning.uvwBits},
                 {"division_ulps", emu::kEnvelopePass.divisionUlps}}},
               {"failures", failureList_}};
  const std::string who = judged_ == "gl" ? "GL" : "emulated";
  // Blind where some sample may take any of the 256 codes of a channel: nothing GL returns there
  // could fail it, so it judges nothing (concludeFromOracles).
  const bool blind = widestCodes_ >= 255;
  o.figures["blind"] = blind;
  if (judged_ == "gl" && !blind) o.judges = Judge::Envelope;
  if (failures_) {
    o.verdict = Verdict::Fail;
    o.summary =
        std::to_string(failures_) + " of " + std::to_string(samples_) + " " + who + " samples outside the envelope";
    for (std::size_t i = 0; i < std::min<std::size_t>(3, failureList_.size()); ++i) {
      const auto& f = failureList_[i];
      o.summary += (i ? "; " : ": ") + f["sample"].dump() + " step " + f["step"].dump() + " " +
                   f["channel"].get<std::string>() + " = " + f["value"].dump() + " not in " + f["allowed"].dump();
    }
  } else if (warnings_) {
    o.verdict = Verdict::Warn;
    o.summary = std::to_string(warnings_) + " of " + std::to_string(samples_) + " " + who +
                " samples only inside the relaxed (quality warning) envelope";
  } else {
    o.verdict = Verdict::Pass;
    o.summary = "all " + std::to_string(samples_) + " " + who +
                " samples inside the envelope (widest per-channel hull of the allowed colours: " +
                std::to_string(widestCodes_) + " codes)";
  }
  if (blind)
    o.summary +=
        "; blind here: it allows every code of a channel at some sample, so only the exact oracle can judge "
        "this scene's output";
  return o;
}

std::vector<PixelValues> TimeVaryingEnvelopeOracle::worstPixels() const {
  // Rank each kind by score (worst first, earlier samples first on ties), interleave the wrong
  // kinds, fill with warnings; the ideal differences only when nothing is wrong.
  std::vector<std::vector<std::size_t>> byKind(4);
  for (std::size_t i = 0; i < candidates_.size(); ++i)
    byKind[static_cast<std::size_t>(candidates_[i].kind)].push_back(i);
  for (auto& list : byKind)
    std::stable_sort(list.begin(), list.end(),
                     [&](std::size_t a, std::size_t b) { return candidates_[a].score > candidates_[b].score; });
  // One entry per pixel position: an exact mismatch outside the envelope is listed once.
  std::vector<PixelValues> out;
  auto take = [&](std::size_t i) {
    const PixelValues& v = candidates_[i].values;
    const bool seen = std::any_of(out.begin(), out.end(),
                                  [&](const PixelValues& o) { return o.x == v.x && o.y == v.y && o.k == v.k; });
    if (!seen && out.size() < kMaxWorstPixels) out.push_back(v);
  };
  for (std::size_t i : interleaveRanked({byKind[0], byKind[1]}, 4 * kMaxWorstPixels)) take(i);
  for (std::size_t i : byKind[2]) take(i);
  if (out.empty())
    for (std::size_t i : byKind[3]) take(i);
  return out;
}

}  // namespace voxref::conf
