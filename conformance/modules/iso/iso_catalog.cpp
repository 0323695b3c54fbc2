#include "conformance/modules/iso/iso_catalog.h"
#include "conformance/framework/stopwatch.h"

#include <chrono>
#include <cmath>

#include "conformance/framework/case_context.h"
#include "conformance/framework/report/case_images.h"
#include "conformance/io/atomic_file.h"
#include "conformance/io/image_io.h"
#include "conformance/modules/iso/iso_session.h"
#include "conformance/modules/iso/mesh_image_compare.h"
#include "conformance/modules/iso/surface_accuracy.h"
#include "fixtures/raycast/mesh_raycast.h"
#include "fixtures/raycast/trilinear_isosurface.h"
#include "gpu/iso_gl.h"
#include "reference/iso/diamond_bounds.h"
#include "reference/iso/extraction.h"
#include "reference/iso/grid_field.h"
#include "reference/leb/gradients.h"

namespace voxref::conf {
namespace {

// The frame a case's report shows (images and magnified pixels): the one with the most failing
// pixels, else the one whose depths come closest to their allowance.
struct ShownFrame {
  const IsoFrame* frame = nullptr;
  std::size_t failures = 0;
  MeshImageAgreement agreement;
  void consider(const IsoFrame& f, const MeshImageAgreement& a) {
    const std::size_t n = a.coverageFailures + a.depthFailures + a.visibilityFailures;
    if (frame && (n < failures || (n == failures && a.maxDepthOverBound <= agreement.maxDepthOverBound))) return;
    frame = &f;
    failures = n;
    agreement = a;
  }
};

void showFrame(CaseContext& ctx, CaseResult& r, const ShownFrame& shown, bool writeImages) {
  const IsoFrame& f = *shown.frame;
  r.figures["shown_frame"] = f.frame;
  for (const MeshPixel& p : shown.agreement.worst) {
    PixelValues v{p.x, p.y, f.frame, "mesh_image", p.glDepth, std::nan(""), p.truthDepth, std::nullopt};
    if (std::isfinite(p.allowance)) v.allowed = std::make_pair(p.planeDepth - p.allowance, p.planeDepth + p.allowance);
    r.worstPixels.push_back(v);
  }
  if (!writeImages) return;
  const std::size_t n = static_cast<std::size_t>(f.gl.width) * static_cast<std::size_t>(f.gl.height);
  ref::Image glShade{f.gl.width, f.gl.height, std::vector<double>(n)},
      truthShade{f.truth.width, f.truth.height, std::vector<double>(n)};
  std::vector<PixelFlag> flags(n, PixelFlag::None);
  for (std::size_t i = 0; i < n; ++i) {
    glShade.pixels[i] = (f.gl.rgba[i][0] + f.gl.rgba[i][1] + f.gl.rgba[i][2]) / (3.0 * 255.0);
    truthShade.pixels[i] = f.truth.shade[i];
    if (shown.agreement.failure[i] != MeshPixelFailure::None) flags[i] = PixelFlag::EnvelopeFail;
  }
  io::ensureDirectory(ctx.outDir() / "images");
  r.images.rendered = caseImageName(r.id, "rendered");
  io::writePng(ctx.outDir() / r.images.rendered, grayPreview(glShade, 1.0));
  r.images.reference = caseImageName(r.id, "reference");
  io::writePng(ctx.outDir() / r.images.reference, grayPreview(truthShade, 1.0));
  r.images.errorMask = caseImageName(r.id, "error_mask");
  io::writePng(ctx.outDir() / r.images.errorMask, errorMaskPreview(glShade, 1.0, flags));
}

// The finding of a driver that drops the fragments of a shader reading gl_PrimitiveID without a
// geometry shader (gpu/iso_gl.h, checkPrimitiveIdGl): measured on GL in every frame case, so that
// a black mesh image is reported as what it is.
constexpr const char* kPrimitiveIdFinding = "gl.fragment.primitive_id_without_geometry_shader_drops_fragments";

std::optional<Finding> primitiveIdFinding(const gpu::PrimitiveIdCheck& c) {
  if (!c.driverDropsPrimitiveIdDraws()) return std::nullopt;
  return Finding{
      kPrimitiveIdFinding,
      "a fragment shader that reads gl_PrimitiveID with no geometry shader bound draws " +
          std::to_string(c.drawnWithId) + " of " + std::to_string(c.pixels) +
          " pixels of a triangle that covers the target, and raises no GL error; the same program writing a "
          "constant id draws all " +
          std::to_string(c.drawnByControl) +
          " (GL 4.6 section 15.2.2: without a geometry shader "
          "gl_PrimitiveID is the primitive's number in the draw)",
      {{"check_pixels", c.pixels}, {"drawn_with_primitive_id", c.drawnWithId}, {"drawn_by_control", c.drawnByControl}}};
}

CaseResult notRun(CaseResult r, const std::string& why) {
  r.status = Status::Skip;
  r.message = why;
  return r;
}

// What every frame of a scene measured, summed; and each frame's figures.
struct FramesTally {
  std::size_t falseCulls = 0, culledInvisible = 0, invisible = 0, tests = 0, triangles = 0;
  std::size_t coverageFail = 0, depthFail = 0, visibilityFail = 0, otherAllowed = 0, same = 0;
  double worstOverBound = 0.0, worstDepth = 0.0;
  std::size_t frames = 0;
  nlohmann::json perFrame = nlohmann::json::array();
  ShownFrame shown;
};

void addFrame(FramesTally& t, const IsoFrame& f) {
  const MeshImageAgreement a = compareMeshImages(f.mesh, f.gl, f.truth, f.camera);
  t.shown.consider(f, a);
  ++t.frames;
  t.falseCulls += f.falseCulls;
  t.culledInvisible += f.culledInvisible;
  t.invisible += f.invisibleCandidates;
  t.tests += f.occlusionTests;
  t.triangles += f.triangles;
  t.coverageFail += a.coverageFailures;
  t.depthFail += a.depthFailures;
  t.visibilityFail += a.visibilityFailures;
  t.otherAllowed += a.otherTriangleAllowed;
  t.same += a.sameTriangle;
  t.worstOverBound = std::max(t.worstOverBound, a.maxDepthOverBound);
  t.worstDepth = std::max(t.worstDepth, a.maxDepthDifference);
  t.perFrame.push_back({{"frame", f.frame},
                        {"isovalue", f.isovalue},
                        {"splits", f.refinement.splits},
                        {"merges", f.refinement.merges},
                        {"split_queue", f.refinement.splitQueue},
                        {"merge_queue", f.refinement.mergeQueue},
                        {"occlusion_tests", f.occlusionTests},
                        {"culled", f.culled},
                        {"false_culls", f.falseCulls},
                        {"visible_diamonds", f.visibleDiamonds},
                        {"triangles", f.triangles},
                        {"pages_decoded_total", f.pagesDecoded},
                        {"same_triangle_pixels", a.sameTriangle},
                        {"other_triangle_allowed", a.otherTriangleAllowed},
                        {"coverage_failures", a.coverageFailures},
                        {"depth_failures", a.depthFailures},
                        {"visibility_failures", a.visibilityFailures},
                        {"max_depth_difference", a.maxDepthDifference}});
}

// No false cull, or for the negative control (a culler that culls everything it tests) some.
OracleResult occlusionOracle(const FramesTally& t, bool cullEveryTested) {
  const double efficiency = t.invisible == 0 ? 0.0 : static_cast<double>(t.culledInvisible) / t.invisible;
  const bool ok = cullEveryTested ? t.falseCulls > 0 : t.falseCulls == 0;
  return {"occlusion",
          ok ? Verdict::Pass : Verdict::Fail,
          std::to_string(t.falseCulls) + " false culls over " + std::to_string(t.frames) + " frames; " +
              std::to_string(t.tests) + " occlusion tests; culled " + std::to_string(t.culledInvisible) + " of " +
              std::to_string(t.invisible) + " invisible candidates (" +
              std::to_string(std::lround(100.0 * efficiency)) + " %)",
          {{"false_culls", t.falseCulls}, {"efficiency", efficiency}, {"tests", t.tests}},
          Judge::IsoGeometry};
}

// Every occlusion test of every frame counted by GL's two counters (gpu/iso_gl.h, SampleCounter),
// which the GL and GLSL specifications make equal box for box; not run where the context lacks the
// buffer counter (`problem`).
OracleResult sampleCountersOracle(const std::vector<IsoFrame>& frames, const std::string& problem) {
  if (!problem.empty()) return {"sample_counters", Verdict::NotRun, problem, {}, Judge::GlBehaviour};
  SampleCountComparison all;
  for (const IsoFrame& f : frames) accumulate(all, f.counters);
  return {"sample_counters",
          all.differing == 0 ? Verdict::Pass : Verdict::Fail,
          std::to_string(all.differing) + " of " + std::to_string(all.boxes) +
              " occlusion tests counted differently by GL_SAMPLES_PASSED queries and by a storage buffer after "
              "early fragment tests (" +
              std::to_string(all.verdictsDiffering) + " of them hidden by one count, visible by the other)" +
              (all.first.empty() ? "" : "; first: " + all.first),
          {{"tests", all.boxes}, {"differing", all.differing}, {"verdicts_differing", all.verdictsDiffering}},
          Judge::GlBehaviour};
}

// GL draws each frame's mesh as Embree sees it (mesh_image_compare.h); `driverNote` names a driver
// finding that explains missing pixels.
OracleResult meshImageOracle(const FramesTally& t, const std::string& driverNote) {
  const bool agree = t.coverageFail == 0 && t.depthFail == 0 && t.visibilityFail == 0;
  return {"mesh_image",
          agree ? Verdict::Pass : Verdict::Fail,
          std::to_string(t.coverageFail) + " coverage, " + std::to_string(t.depthFail) + " depth and " +
              std::to_string(t.visibilityFail) + " visibility failures" + driverNote + "; " + std::to_string(t.same) +
              " pixels show the same triangle, " + std::to_string(t.otherAllowed) +
              " another one within the snapping allowance; worst depth " + std::to_string(t.worstOverBound) +
              " of its allowance (" + std::to_string(t.worstDepth) + " grid units)",
          {{"coverage_failures", t.coverageFail},
           {"depth_failures", t.depthFail},
           {"visibility_failures", t.visibilityFail},
           {"same_triangle_pixels", t.same},
           {"other_triangle_allowed", t.otherAllowed}},
          Judge::IsoGeometry};
}

// Occlusion and mesh-image oracles over every frame of a scene.
CaseResult judgeFrames(CaseContext& ctx, const std::string& id, const std::string& description, const IsoScene& scene,
                       bool expectEmpty) {
  CaseResult r;
  r.id = id;
  r.system = "iso";
  r.description = description;
  if (ctx.gl() == nullptr) return notRun(r, "no GL context");
  const std::optional<Finding> primitiveId = primitiveIdFinding(gpu::checkPrimitiveIdGl(*ctx.gl()));
  IsoRunOptions options;
  options.keepImages = true;
  options.threads = ctx.threads();
  const std::string noBufferCounter = gpu::sampleCounterProblem(*ctx.gl(), gpu::SampleCounter::Buffer);
  options.compareCounters = noBufferCounter.empty();
  const auto t0 = Clock::now();
  const std::vector<IsoFrame> frames = runIsoFrames(*ctx.gl(), scene, options);
  r.secondsGl = secondsSince(t0);
  FramesTally t;
  for (const IsoFrame& f : frames) addFrame(t, f);
  r.figures["frames"] = t.perFrame;
  r.figures["scene"] = {{"data", scene.data},
                        {"dims", scene.dims},
                        {"isovalue", scene.isovalue},
                        {"frames", scene.path.frames},
                        {"threshold_px", scene.budget.threshold},
                        {"max_splits", scene.budget.maxSplits}};
  if (primitiveId) {  // findings inform; the verdict stays the mesh image's
    Finding f = *primitiveId;
    f.figures["samples_changed"] = t.coverageFail;  // pixels the truth covers that GL left empty
    r.findings.push_back(f);
  }
  const std::string driverNote = primitiveId && t.coverageFail > 0
                                     ? " (the driver draws no fragment of a shader reading gl_PrimitiveID: finding " +
                                           std::string(kPrimitiveIdFinding) + ")"
                                     : "";
  r.oracles = {occlusionOracle(t, scene.cullEveryTested), meshImageOracle(t, driverNote),
               sampleCountersOracle(frames, noBufferCounter)};
  if (expectEmpty)
    r.oracles.push_back({"empty",
                         t.triangles == 0 ? Verdict::Pass : Verdict::Fail,
                         std::to_string(t.triangles) + " triangles for an isovalue outside the data range",
                         {}});
  concludeFromOracles(r);
  if (t.shown.frame)
    showFrame(ctx, r, t.shown, ctx.writeAllImages() || r.status == Status::Fail || r.status == Status::Warn);
  return r;
}

// Extracted surface against the exact trilinear isosurface, per threshold, from the first camera.
CaseResult judgeAccuracy(CaseContext& ctx, const std::string& id, const IsoScene& scene) {
  CaseResult r;
  r.id = id;
  r.system = "iso";
  r.description = "extracted surface vs the exact isosurface of the trilinear field, per error threshold";
  const ref::Volume<std::uint16_t> volume = isoSceneVolume(scene);
  ref::DenseGridField field(volume, ref::quantizedGradients(volume));
  const ref::DiamondBounds bounds = ref::computeDiamondBounds(field.grid(), field.values(), ctx.threads());
  const ref::ViewCamera camera = ref::orbitCamera(scene.path, 0, scene.camera);
  const fx::RayImage exact = fx::castTrilinearIsosurface(volume, scene.isovalue, camera, ctx.threads());
  nlohmann::json rows = nlohmann::json::array(), seconds = nlohmann::json::array();
  std::string summary;
  for (double threshold : {8.0, 2.0, 0.5, 0.0}) {
    const auto t0 = Clock::now();
    const ThresholdSurface surface = extractAtThreshold(bounds, field, camera, scene.isovalue, threshold);
    seconds.push_back({{"threshold_px", threshold}, {"refine_and_extract_s", secondsSince(t0)}});
    const SurfaceError e = compareSurfaces(fx::castMesh(surface.mesh, camera, ctx.threads()), exact);
    rows.push_back({{"threshold_px", threshold},
                    {"triangles", surface.stats.triangles},
                    {"split_diamonds", surface.splitDiamonds},
                    {"mean_depth_error", e.meanDepth},
                    {"max_depth_error", e.maxDepth},
                    {"silhouette_pixels", e.silhouettePixels}});
    summary += "threshold " + std::to_string(threshold).substr(0, 4) + ": " + std::to_string(surface.stats.triangles) +
               " triangles, mean depth error " + std::to_string(e.meanDepth).substr(0, 6) + ", " +
               std::to_string(e.silhouettePixels) + " silhouette px; ";
  }
  r.figures["thresholds"] = rows;
  r.timings["thresholds"] = seconds;
  r.oracles.push_back({"ideal", Verdict::Info, summary, {}});
  concludeFromOracles(r);  // the CPU's refinement against Embree: informative, never a pass on GL (a skip)
  return r;
}

}  // namespace

std::vector<Case> isoCases() {
  std::vector<Case> cases;
  auto frames = [&](const std::string& id, const std::string& description, const IsoScene& s, bool empty) {
    cases.push_back({id, "iso", description,
                     [=](CaseContext& ctx) { return judgeFrames(ctx, id, description, s, empty); }, std::nullopt});
  };
  for (const IsoScene& s : builtInIsoScenes()) {
    frames("iso.frames." + s.name,
           "occlusion culling never culls a visible diamond, and GL draws each frame's mesh as Embree sees it (" +
               s.data + ")",
           s, false);
    const std::string id = "iso.accuracy." + s.name;
    cases.push_back({id, "iso", "extracted vs exact trilinear isosurface per error threshold (" + s.data + ")",
                     [=](CaseContext& ctx) { return judgeAccuracy(ctx, id, s); }, std::nullopt});
  }
  IsoScene broken = builtInIsoScenes().front();
  broken.name = "broken_culler_is_caught";
  broken.path.frames = 3;
  broken.cullEveryTested = true;
  frames("iso.control.broken_culler_is_caught",
         "negative control: a culler that culls every diamond it tests is caught culling visible ones", broken, false);
  for (const IsoScene& s : hardIsoScenes())
    frames("iso.hard." + s.name, "hard case " + s.name + ": occlusion and mesh images through the frame loop", s,
           s.name == "isovalue_outside_range" || s.name == "empty_volume" || s.name == "full_volume");
  return cases;
}

}  // namespace voxref::conf
