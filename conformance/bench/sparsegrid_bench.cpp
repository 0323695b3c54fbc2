#include "conformance/bench/sparsegrid_bench.h"
#include "conformance/framework/selection.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "conformance/bench/study.h"
#include "conformance/framework/compare.h"
#include "conformance/framework/progress.h"
#include "conformance/modules/catalog.h"
#include "conformance/modules/sparsegrid/prepared_scene.h"
#include "conformance/modules/sparsegrid/sparsegrid_catalog.h"
#include "emulation/combination_emu.h"
#include "gpu/combination_gl.h"
#include "gpu/gl_error.h"
#include "reference/common/frame_sampling.h"
#include "reference/common/parallel.h"
#include "reference/sparsegrid/full_grid.h"

namespace voxref::conf {
namespace {

using Clock = std::chrono::steady_clock;

// One plane of `frame` as a frame of its own (still on the float32 lattice).
ref::PlaneFrame planeOf(const ref::PlaneFrame& frame, int k) {
  ref::PlaneFrame f = frame;
  f.origin = frame.origin + static_cast<double>(k) * frame.dz;
  f.planes = 1;
  return f;
}

// Time to sample every point of `frame` with fn. When a sample of evenly spread planes predicts
// more than `budget` seconds, the time is extrapolated from those planes and marked estimated
// (as the paper marks its estimates).
Timing sampleTiming(const ref::PlaneFrame& frame, const std::function<double(glm::dvec3)>& fn, int threads,
                    double budget) {
  const int probes = std::min(frame.planes, 8);
  double probeSeconds = 0.0;
  for (int p = 0; p < probes; ++p) {
    const ref::PlaneFrame one = planeOf(frame, (2 * p + 1) * frame.planes / (2 * probes));
    const auto t0 = Clock::now();
    (void)ref::sampleFrame(one, fn, threads);
    probeSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
  }
  const double predicted = probeSeconds / probes * frame.planes;
  if (predicted > budget) return {predicted, predicted, predicted, 0, true};
  return measure([&] { (void)ref::sampleFrame(frame, fn, threads); });
}

SparseGridScene benchScene(int level, int width, int planes) {
  SparseGridScene s = defaultSparseGridScene();
  s.grid.level = level;
  s.framebuffer = ref::FramebufferFormat::RGBA16;  // the nearest GL has to the paper's 12-bit buffer
  s.shading.mode = ref::RenderMode::XRay;          // the paper timed X-ray images
  s.width = s.height = width;
  s.planes = planes;
  return s;
}

BenchTable timeTable(const BenchOptions& o, gpu::Context& gl, const emu::PrecisionProfile* profile) {
  const int first = o.quick ? 3 : 5, last = o.quick ? 5 : 11;
  const int width = o.quick ? 32 : 200, planes = o.quick ? 16 : 128;
  const double budget = o.quick ? 2.0 : 30.0;
  BenchTable t;
  t.id = "sparsegrid.table1_time";
  t.title = "Sparse grids, Table 1 on this machine: seconds per frame (" + std::to_string(width) + "x" +
            std::to_string(width) + " pixels, " + std::to_string(planes) + " samples per ray, X-ray)";
  t.columns = {"method"};
  for (int l = first; l <= last; ++l) t.columns.push_back("level " + std::to_string(l));
  std::vector<std::string> build{"sparse grid build (sampling + hierarchization)"},
      direct{"sparse grid, direct (eq. 7)"}, combination{"combination technique, CPU double (eq. 11)"},
      glRow{"combination on GL: " + gl.info().renderer},
      emuRow{"combination emulated: profile " + std::string(profile ? profile->name : "none")},
      full{"full-grid extraction"};
  Progress progress("voxref bench: table 1", last - first + 1);
  for (int level = first; level <= last; ++level) {
    progress.update(level - first, "level " + std::to_string(level));
    const SparseGridScene scene = benchScene(level, width, planes);
    PreparedScene prepared;
    const Timing buildTime = measure([&] { prepared = prepareScene(scene); });
    const ref::SparseGrid grid = ref::SparseGrid::fromField(scene.grid, loadField(scene.data));
    const Timing directTime = sampleTiming(
        prepared.frame, [&](glm::dvec3 p) { return grid.value(p); }, o.threads, budget);
    const Timing combTime = sampleTiming(
        prepared.frame, [&](glm::dvec3 p) { return prepared.combination->value(p); }, o.threads, budget);
    nlohmann::json row = {{"level", level},
                          {"build", toJson(buildTime)},
                          {"direct", toJson(directTime)},
                          {"combination", toJson(combTime)}};
    build.push_back(formatSeconds(buildTime));
    direct.push_back(formatSeconds(directTime));
    combination.push_back(formatSeconds(combTime));
    try {
      const Timing g = measure([&] {
        (void)gpu::renderCombinationGl(gl, prepared.textures, prepared.frame, scene.sampler, scene.framebuffer);
      });
      glRow.push_back(formatSeconds(g));
      row["gl"] = toJson(g);
    } catch (const gpu::GlUnsupported& e) {
      glRow.push_back("n/a");
      row["gl"] = {{"not_run", e.what()}};
    }
    if (profile) {
      const Timing e = measure([&] {
        (void)emu::emulateCombination(prepared.textures, prepared.frame, scene.sampler, scene.framebuffer, *profile,
                                      {false, o.threads});
      });
      emuRow.push_back(formatSeconds(e));
      row["emulation"] = toJson(e);
    } else {
      emuRow.push_back("n/a");
    }
    if (ref::fullGridBytes(level) <= (std::size_t{4} << 30)) {
      const Timing f = measure([&] { (void)ref::extractFullGrid(grid); });
      full.push_back(formatSeconds(f));
      row["full_grid_extraction"] = toJson(f);
    } else {
      full.push_back("n/a");
      row["full_grid_extraction"] = {
          {"not_run", "needs " + bytesText(static_cast<double>(ref::fullGridBytes(level))) + " of doubles"}};
    }
    t.data["levels"].push_back(row);
  }
  progress.finish();
  t.rows = {build, direct, combination, glRow, emuRow, full};
  if (!o.quick) {
    t.rows.push_back(
        {"paper: sparse grid (SGI O2, 1999)", "755 s", "1040 s", "1380 s", "1935 s", "2750 s", "3910 s*", "5400 s*"});
    t.rows.push_back({"paper: combination", "83 s", "124 s", "173 s", "233 s", "309 s", "454 s", "726 s"});
    t.rows.push_back(
        {"paper: OpenGL (RealityEngine II)", "3.6 s", "4.5 s", "5.5 s", "6.8 s", "8.4 s", "10.3 s", "12.5 s"});
    t.rows.push_back(
        {"paper: full grid extraction", "4.93 s", "53.9 s", "593 s", "1.8 h", "20 h*", "9.5 d*", "105 d*"});
  }
  t.notes =
      "Gaussian-blob data with boundary points; textures r16 padded to 2^(l+1) (the paper's), framebuffer rgba16 "
      "(the paper had 12 bits; GL has no 12-bit buffer). CPU paths on " +
      std::to_string(ref::workerCount(o.threads)) + " thread(s). Medians of up to 5 runs. * = extrapolated from " +
      "8 evenly spread planes because the whole frame would take more than " +
      std::to_string(static_cast<int>(budget)) +
      " s. Levels 11 and 12 on GL draw 2048-texel bricks (GL_MAX_3D_TEXTURE_SIZE here: " +
      std::to_string(gl.info().max3DTextureSize) +
      "); n/a for extraction: the full grid of doubles exceeds 4 GB. Full-grid extraction here dehierarchizes "
      "(linear in the grid size); the paper evaluated the sparse grid at every node.";
  return t;
}

BenchTable memoryTable(const BenchOptions& o) {
  const int first = o.quick ? 3 : 5, last = o.quick ? 5 : 11;
  BenchTable t;
  t.id = "sparsegrid.table2_memory";
  t.title = "Sparse grids, Table 2: memory (4-byte values; GL textures 2-byte r16)";
  t.columns = {"quantity"};
  for (int l = first; l <= last; ++l) t.columns.push_back("level " + std::to_string(l));
  std::vector<std::string> fullPts{"points of full grid"}, fullMem{"full grid"},
      sparseZero{"sparse grid, zero boundary (points)"}, sparseZeroMem{"sparse grid, zero boundary"},
      sparseB{"sparse grid with boundary (points)"}, sparseBMem{"sparse grid with boundary"}, comb{"combination grids"},
      glPadded{"GL textures, padded 2^(l+1) (paper)"}, glExact{"GL textures, exact 2^l + 1"}, grids{"number of grids"},
      positive{"positive grids (n+)"};
  for (int n = first; n <= last; ++n) {
    const double side = std::ldexp(1.0, n) + 1;
    const std::size_t zero = ref::SubspaceSet({n, false}).pointCount(),
                      withB = ref::SubspaceSet({n, true}).pointCount();
    double combPoints = 0, padded = 0, exact = 0;
    int pos = 0;
    const auto shapes = ref::combinationGridShapes(n);
    for (const auto& s : shapes) {
      double p = 1, pd = 1;
      for (int a = 0; a < 3; ++a) {
        p *= std::ldexp(1.0, s.levels[a]) + 1;
        pd *= std::ldexp(1.0, s.levels[a] + 1);
      }
      combPoints += p;
      padded += pd;
      exact += p;
      pos += s.coefficient > 0;
    }
    fullPts.push_back(std::to_string(static_cast<long>(side)) + "^3");
    fullMem.push_back(bytesText(side * side * side * 4));
    sparseZero.push_back(std::to_string(zero));
    sparseZeroMem.push_back(bytesText(4.0 * zero));
    sparseB.push_back(std::to_string(withB));
    sparseBMem.push_back(bytesText(4.0 * withB));
    comb.push_back(bytesText(4 * combPoints));
    glPadded.push_back(bytesText(2 * padded));
    glExact.push_back(bytesText(2 * exact));
    grids.push_back(std::to_string(shapes.size()));
    positive.push_back(std::to_string(pos));
    t.data["levels"].push_back({{"level", n},
                                {"full_grid_points", side * side * side},
                                {"sparse_points_zero_boundary", zero},
                                {"sparse_points_with_boundary", withB},
                                {"combination_points", combPoints},
                                {"gl_texels_padded", padded},
                                {"gl_texels_exact", exact},
                                {"grids", shapes.size()},
                                {"positive_grids", pos}});
  }
  t.rows = {fullPts, fullMem, sparseZero, sparseZeroMem, sparseB, sparseBMem, comb, glPadded, glExact, grids, positive};
  if (!o.quick) {
    t.rows.push_back({"paper: full grid", "128 kB", "1 MB", "8 MB", "64 MB", "512 MB", "4 GB", "32 GB"});
    t.rows.push_back({"paper: sparse grid", "6 kB", "15 kB", "35 kB", "83 kB", "200 kB", "450 kB", "1 MB"});
    t.rows.push_back({"paper: combination", "22 kB", "59 kB", "152 kB", "377 kB", "914 kB", "2.1 MB", "5 MB"});
    t.rows.push_back({"paper: OpenGL", "43 kB", "124 kB", "338 kB", "884 kB", "2.2 MB", "5.4 MB", "13.1 MB"});
    t.rows.push_back({"paper: num. low res. full grids", "31", "46", "64", "85", "109", "136", "166"});
  }
  t.notes =
      "Counts are exact (point counts are checked against an independent count in the unit tests); kB = 1024 bytes.";
  return t;
}

BenchTable accuracyTable(const BenchOptions& o, gpu::Context& gl, const emu::PrecisionProfile* profile) {
  // Up to level 8: the study (study.sparsegrid) has every precision variant side by side; this
  // table shows how the formats' errors move with the level, within the bench's 15 minutes.
  const int first = o.quick ? 3 : 5, last = o.quick ? 4 : 8;
  const int width = o.quick ? 24 : 100, planes = o.quick ? 12 : 64;
  BenchTable t;
  t.id = "sparsegrid.accuracy";
  t.title = "Sparse grids: what accuracy costs, per framebuffer format (" + std::to_string(width) + "x" +
            std::to_string(width) + "x" + std::to_string(planes) + " samples, r16 padded textures)";
  t.columns = {"framebuffer",  "level", "max abs error", "max error where reference >= 0", "RMSE", "PSNR dB",
               "error in LSB", "GL s",  "emulation s"};
  const ref::FramebufferFormat formats[] = {ref::FramebufferFormat::RGBA8, ref::FramebufferFormat::RGBA12,
                                            ref::FramebufferFormat::RGBA16, ref::FramebufferFormat::RGBA16F,
                                            ref::FramebufferFormat::RGBA32F};
  Progress progress("voxref bench: accuracy", (last - first + 1) * 5);
  long step = 0;
  for (int level = first; level <= last; ++level) {
    SparseGridScene scene = benchScene(level, width, planes);
    const PreparedScene prepared = prepareScene(scene);
    const ref::SampleStack reference = referencePlanes(prepared, o.threads);
    for (ref::FramebufferFormat fb : formats) {
      progress.update(step++, std::string(ref::name(fb)) + " level " + std::to_string(level));
      std::optional<ref::CodePlanes> glPlanes, emuPlanes;
      Timing glTime, emuTime;
      std::string glText = "n/a", emuText = "n/a";
      if (ref::existsInGl(fb)) try {
          glTime = measure(
              [&] { glPlanes = gpu::renderCombinationGl(gl, prepared.textures, prepared.frame, scene.sampler, fb); });
          glText = formatSeconds(glTime);
        } catch (const gpu::GlUnsupported&) {
        }
      if (profile) {
        emuTime = measure([&] {
          emuPlanes = emu::emulateCombination(prepared.textures, prepared.frame, scene.sampler, fb, *profile,
                                              {false, o.threads})
                          .planes;
        });
        emuText = formatSeconds(emuTime);
      }
      const ref::CodePlanes* judged = glPlanes ? &*glPlanes : emuPlanes ? &*emuPlanes : nullptr;
      if (!judged) continue;
      const ref::SampleStack values = ref::toSampleStack(*judged, prepared.textures.readbackScale);
      const ErrorFigures e = compareValues(values.values, reference.values, 1.0);
      // Fixed-point buffers cannot hold the interpolant's overshoot below 0: separate that loss.
      double nonNegativeMax = 0.0;
      for (std::size_t i = 0; i < values.values.size(); ++i)
        if (reference.values[i] >= 0.0)
          nonNegativeMax = std::max(nonNegativeMax, std::fabs(values.values[i] - reference.values[i]));
      const int bits = ref::unormBits(fb);
      const double lsb = bits ? prepared.textures.readbackScale / (std::ldexp(1.0, bits) - 1.0) : 0.0;
      char maxAbs[32], maxNonNeg[32], rmse[32], psnr[32], inLsb[32];
      std::snprintf(maxAbs, sizeof maxAbs, "%.3g", e.maxAbs);
      std::snprintf(maxNonNeg, sizeof maxNonNeg, "%.3g", nonNegativeMax);
      std::snprintf(rmse, sizeof rmse, "%.3g", e.rmse);
      std::snprintf(psnr, sizeof psnr, "%.1f", e.psnrDb);
      std::snprintf(inLsb, sizeof inLsb, bits ? "%.1f" : "-", bits ? nonNegativeMax / lsb : 0.0);
      t.rows.push_back({std::string(ref::name(fb)) + (glPlanes ? "" : " (emulated)"), std::to_string(level), maxAbs,
                        maxNonNeg, rmse, psnr, inLsb, glText, emuText});
      t.data["rows"].push_back({{"framebuffer", ref::name(fb)},
                                {"level", level},
                                {"max_abs_error", e.maxAbs},
                                {"max_abs_error_where_reference_nonnegative", nonNegativeMax},
                                {"rmse", e.rmse},
                                {"psnr_db", std::isfinite(e.psnrDb) ? nlohmann::json(e.psnrDb) : nlohmann::json("inf")},
                                {"judged", glPlanes ? "gl" : "emulation"},
                                {"gl", glPlanes ? toJson(glTime) : nlohmann::json(nullptr)},
                                {"emulation", emuPlanes ? toJson(emuTime) : nlohmann::json(nullptr)}});
    }
  }
  progress.finish();
  t.notes =
      "Errors of the read-back planes (times n+) against the double combination technique at the same sample points "
      "(values in [0, 1]; PSNR against peak 1). Sparse-grid interpolants overshoot below 0 near steep data, which "
      "fixed-point buffers clamp: the second error column leaves those samples out. 'error in LSB' is that error in "
      "units of n+ / (2^b - 1), the framebuffer's quantum after the read-back scale. The GL path and the emulation "
      "give identical bits here "
      "(checked by voxref conform), so one error column serves both. rgba12 has no GL implementation: emulated.";
  return t;
}

}  // namespace

std::vector<std::string> sparseGridBenchIds() {
  return {"sparsegrid.table1_time", "sparsegrid.table2_memory", "sparsegrid.accuracy", "study.sparsegrid"};
}

std::vector<BenchTable> sparseGridBench(const BenchOptions& o, gpu::Context& gl, const emu::PrecisionProfile* profile) {
  std::vector<BenchTable> tables;
  if (globMatch(o.filter, "sparsegrid.table1_time")) tables.push_back(timeTable(o, gl, profile));
  if (globMatch(o.filter, "sparsegrid.table2_memory")) tables.push_back(memoryTable(o));
  if (globMatch(o.filter, "sparsegrid.accuracy")) tables.push_back(accuracyTable(o, gl, profile));
  if (globMatch(o.filter, "study.sparsegrid")) tables.push_back(sparseGridStudy(o, gl, profile));
  return tables;
}

}  // namespace voxref::conf
