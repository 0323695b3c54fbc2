#include "conformance/modules/sparsegrid/figure9_conf.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "conformance/framework/compare.h"
#include "conformance/modules/sparsegrid/combination_conf.h"

namespace voxref::conf {
namespace {

// Samples on the 1/8 lattice of the unit cube, 9 x 9 x 9: every node of the level-2 grids and
// every midpoint between them.
SparseGridScene figure9Scene(ref::ScalingPolicy scaling) {
  SparseGridScene s;
  s.data.field = "figure9";
  s.grid = {2, true};
  s.textures = {ref::TexelFormat::R16, ref::TextureSizing::Padded, scaling};  // padded: exact addresses
  s.framebuffer = ref::FramebufferFormat::RGBA16;                             // fixed point: it clamps
  s.shading.mode = ref::RenderMode::Mip;
  const double h = 1.0 / 8;
  s.camera.origin = glm::dvec3(-h / 2);
  s.camera.dx = glm::dvec3(h, 0, 0);
  s.camera.dy = glm::dvec3(0, h, 0);
  s.camera.dz = glm::dvec3(0, 0, h);
  s.width = s.height = s.planes = 9;
  return s;
}

// Quantization bound of a correct evaluation (scaled, or an order that never clamps wrongly):
// per pass at most 0.5 LSB16 from storing the texel, 0.5 LSB16 from converting the blended
// value, and 2^-24 from the float lerp at weight 0 or 1/2 (the only weights on this lattice with
// padded textures, whose addresses are exact); times the read-back scale.
double quantizationBound(std::size_t passes, double readbackScale) {
  return readbackScale * static_cast<double>(passes) * (1.0 / 65535.0 + std::ldexp(1.0, -24));
}

double maxError(const CombinationPlanes& r) {
  const ref::SampleStack s = ref::toSampleStack(*r.gl, r.readbackScale);
  return compareValues(s.values, r.reference.values, 1.0).maxAbs;
}

CaseResult everyUnscaledOrderFails(CaseContext& ctx) {
  CaseResult result;
  result.id = "sparsegrid.hard.fig9.unscaled_every_order";
  result.system = "sparsegrid";
  result.description = "Fig. 9: without scaling every one of the 60 orders of +A +B +C -N -N fails somewhere";
  SparseGridScene scene = figure9Scene(ref::ScalingPolicy::Unscaled);
  // Passes of the unscaled method: 0..2 add A, B, C; 3 and 4 subtract N (twice).
  std::set<std::vector<int>> seen;  // orders that differ only by swapping the two N passes are one order
  std::vector<int> perm{0, 1, 2, 3, 4};
  std::size_t orders = 0, exactMismatches = 0, mismatchedPixels = 0, correctOrders = 0;
  std::uint64_t maxDistance = 0;
  double smallestFailure = INFINITY, bound = 0.0;
  nlohmann::json perOrder = nlohmann::json::array();
  do {
    std::vector<int> key = perm;
    for (int& p : key) p = std::min(p, 3);
    if (!seen.insert(key).second) continue;
    ++orders;
    scene.passOrder = perm;
    const auto r = computeCombinationPlanes(ctx, scene);
    if (!r->gl) {
      result.status = Status::Skip;
      result.message = r->glNotRun;
      return result;
    }
    result.secondsGl += r->secondsGl;
    result.secondsEmulation += r->secondsEmulation;
    result.secondsReference += r->secondsReference;
    if (r->emulated) {
      const CodeComparison c = compareCodes(*r->gl, r->emulated->planes);
      exactMismatches += c.mismatched;
      maxDistance = std::max(maxDistance, c.maxDistance);
      const std::size_t plane = static_cast<std::size_t>(r->frame.width) * r->frame.height;
      std::vector<std::uint8_t> pixel(plane, 0);
      for (std::size_t s = 0; s < c.mask.size(); ++s) pixel[s % plane] |= c.mask[s];
      for (std::uint8_t m : pixel) mismatchedPixels += m;
    }
    bound = quantizationBound(r->passCount, r->readbackScale);
    const double err = maxError(*r);
    if (err <= bound) ++correctOrders;
    smallestFailure = std::min(smallestFailure, err);
    std::string order;
    for (int p : key) order += std::string(p == 3 ? "-N" : p == 0 ? "+A" : p == 1 ? "+B" : "+C") + " ";
    perOrder.push_back({{"order", order}, {"max_abs_error", err}});
  } while (std::next_permutation(perm.begin(), perm.end()));

  OracleResult exact{"exact",
                     exactMismatches ? Verdict::Fail : Verdict::Pass,
                     std::to_string(exactMismatches) + " samples differ between GL and emulation over all " +
                         std::to_string(orders) + " orders",
                     {{"mismatched_samples", exactMismatches},
                      {"mismatched_pixels", mismatchedPixels},
                      {"max_abs_diff_lsb", maxDistance},
                      {"orders", orders}}};
  exact.judges = Judge::Exact;
  if (!ctx.profile()) exact = {"exact", Verdict::NotRun, "no precision profile for this driver", {}};
  // The derivation predicts an error of at least 0.6 for every order; anything above the
  // quantization bound already shows the clamping failure.
  OracleResult paper{
      "ideal",
      correctOrders == 0 ? Verdict::Pass : Verdict::Fail,
      std::to_string(orders - correctOrders) + " of " + std::to_string(orders) +
          " orders wrong beyond the quantization bound; the least wrong is off by " + std::to_string(smallestFailure),
      {{"orders", orders},
       {"orders_correct", correctOrders},
       {"smallest_max_abs_error", smallestFailure},
       {"quantization_bound", bound},
       {"expected_smallest_error", 0.6},
       {"per_order", perOrder}},
      Judge::Prediction};  // GL's read-back against the paper's prediction: it fails a driver that does not clamp
  result.oracles = {exact, paper};
  result.figures = {{"orders", orders}, {"scene", toJson(scene)}};
  concludeFromOracles(result);
  return result;
}

CaseResult scaledIsCorrect(CaseContext& ctx) {
  const SparseGridScene scene = figure9Scene(ref::ScalingPolicy::Scaled);
  CaseResult result = judgeCombination(ctx, "sparsegrid.hard.fig9.scaled",
                                       "Fig. 9 data with the paper's 1/n+ scaling: every sample right", scene);
  const auto r = ctx.cached<CombinationPlanes>(planeKey(scene), [&] { return computeCombinationPlanes(ctx, scene); });
  if (!r->gl) return result;
  const double err = maxError(*r), bound = quantizationBound(r->passCount, r->readbackScale);
  result.oracles.push_back(
      {"bound",
       err <= bound ? Verdict::Pass : Verdict::Fail,
       "max error " + std::to_string(err) + " against the quantization bound " + std::to_string(bound),
       {{"max_abs_error", err}, {"quantization_bound", bound}},
       Judge::Prediction});
  concludeFromOracles(result);
  return result;
}

}  // namespace

std::vector<Case> figure9Cases() {
  Case unscaled;
  unscaled.id = "sparsegrid.hard.fig9.unscaled_every_order";
  unscaled.system = "sparsegrid";
  unscaled.description = "Fig. 9: without scaling every one of the 60 orders of +A +B +C -N -N fails somewhere";
  unscaled.run = everyUnscaledOrderFails;
  Case scaled;
  scaled.id = "sparsegrid.hard.fig9.scaled";
  scaled.system = "sparsegrid";
  scaled.description = "Fig. 9 data with the paper's 1/n+ scaling: every sample right";
  scaled.run = scaledIsCorrect;
  scaled.scene = toJson(figure9Scene(ref::ScalingPolicy::Scaled));
  return {unscaled, scaled};
}

}  // namespace voxref::conf
