// The buckyball at the paper's size, end to end (issue 18, goal 4; Gregorski et al. 2004,
// section 5: "a 1024^3 buckyball"). Each step is timed and its peak resident memory measured on
// its own: the encoder as a process of its own (`voxref encode --codec leb`, streaming between
// files), the bounds and the frames in this process between resets of its peak (processes.h).
//   1. the volume: gaussian_buckyball sampled as uint8, slice by slice into a file (never held);
//   2. the LEB stream with gradients, from that file;
//   3. the tiered diamond bounds (reference/iso/tiered_bounds.h) from a mapping of the volume;
//   4. the frames of an orbit from the stream (pages decoded on demand) with those bounds, without
//      and with the paper's occlusion culling (GL occlusion queries, then the same boxes counted in
//      one draw: gpu/iso_gl.h), each frame drawn with GL and its ground truth ray cast with Embree
//      (conformance/modules/iso/iso_session.h).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <span>
#include <stdexcept>

#include "conformance/bench/iso_bench.h"
#include "conformance/bench/processes.h"
#include "conformance/bench/study.h"
#include "conformance/framework/progress.h"
#include "conformance/framework/stopwatch.h"
#include "conformance/io/atomic_file.h"
#include "conformance/io/leb_file.h"
#include "conformance/io/mapped_file.h"
#include "conformance/modules/iso/iso_scene.h"
#include "reference/common/fields.h"
#include "reference/common/parallel.h"
#include "reference/iso/tiered_bounds.h"

namespace voxref::conf {
namespace {

constexpr double kGoalBytes = 4e9;
constexpr std::size_t kPageCacheBytes = std::size_t{256} << 20;

void writeBuckyball(const std::filesystem::path& path, const ref::Dims3& d, int threads) {
  std::ofstream out(path, std::ios::binary);
  const std::size_t slice = static_cast<std::size_t>(d[0]) * static_cast<std::size_t>(d[1]);
  const int batch = 2 * ref::workerCount(threads);
  std::vector<std::uint8_t> buffer(slice * static_cast<std::size_t>(batch));
  for (int z0 = 0; z0 < d[2]; z0 += batch) {
    const int n = std::min(batch, d[2] - z0);
    ref::parallelFor(n, threads, [&](int i) {
      ref::sampleGaussianBuckyballSliceU8(d, z0 + i, buffer.data() + slice * static_cast<std::size_t>(i));
    });
    out.write(reinterpret_cast<const char*>(buffer.data()),
              static_cast<std::streamsize>(slice * static_cast<std::size_t>(n)));
  }
  if (!out) throw std::runtime_error("cannot write " + path.string() + " for the isosurface scale bench");
}

struct Step {
  std::string name;
  double seconds = 0, peakBytes = 0;
};

}  // namespace

BenchTable isoScaleBench(const BenchOptions& o, gpu::Context& gl) {
  BenchTable t;
  t.id = kIsoScaleBenchId;
  const int side = o.quick ? 65 : 1025;
  const ref::Dims3 dims{side, side, side};
  const ref::LebGrid grid = ref::lebGridCovering(dims);
  t.title = "Isosurfaces at the paper's size: the Gaussian buckyball " + ref::dimsText(dims) +
            " end to end (time and peak resident memory of each step)";
  t.columns = {
      "step",      "seconds", "peak RSS",    "peak / 4 GB goal", "frame time (queries / refine / extract / GL)",
      "triangles", "culled",  "false culls", "pages decoded",    "Embree s/frame"};
  const std::filesystem::path dir = o.out / "iso-scale";
  io::ensureDirectory(dir);
  const std::string name = "buckyball_" + ref::dimsText(dims);
  const std::filesystem::path raw = dir / (name + ".raw"), streamPath = dir / (name + ".vxleb");
  Progress progress("voxref bench iso.scale", 6);
  std::vector<Step> steps;

  progress.update(0, "volume");
  resetPeakResident();
  auto t0 = Clock::now();
  writeBuckyball(raw, dims, o.threads);
  steps.push_back(
      {"volume: gaussian_buckyball as uint8, slice by slice into a file", secondsSince(t0), peakResidentBytes()});

  progress.update(1, "encode");
  const ProcessRun enc = runVoxref({"encode", "--codec", "leb", "--input", raw.string(), "--dims", std::to_string(side),
                                    std::to_string(side), std::to_string(side), "--out", streamPath.string()});
  steps.push_back(
      {"encode: `voxref encode --codec leb` with gradients, a process of its own", enc.seconds, enc.peakBytes});

  progress.update(2, "bounds");
  resetPeakResident();
  t0 = Clock::now();
  ref::CoarseDiamondBounds coarse;
  {
    const io::MappedFile volume = io::MappedFile::openRead(raw);
    coarse =
        ref::computeCoarseDiamondBounds(grid, std::span<const std::uint8_t>(volume.data(), volume.size()), o.threads);
  }
  steps.push_back({"tiered diamond bounds from a mapping of the volume", secondsSince(t0), peakResidentBytes()});
  const double tableBytes = 8.0 * static_cast<double>(coarse.min.size());
  std::filesystem::remove(raw);

  IsoScene scene = builtInIsoScenes().front();
  scene.name = name;
  aimOrbitAt(scene, dims);
  scene.isovalue = 85.0;
  scene.camera.width = scene.camera.height = o.quick ? 64 : 256;
  scene.path.frames = o.quick ? 2 : 8;
  scene.budget.maxSplits = o.quick ? 5000 : 40000;
  const double streamBytes = static_cast<double>(std::filesystem::file_size(streamPath));
  t.data["volume"] = {{"dims", {side, side, side}},
                      {"stream_bytes", streamBytes},
                      {"bounds_table_bytes", tableBytes},
                      {"page_cache_bytes", kPageCacheBytes},
                      {"scene", toJson(scene)}};
  t.data["rows"] = nlohmann::json::array();
  for (const auto& s : steps) {
    t.rows.push_back({s.name, formatNumber("%.1f", s.seconds), bytesText(s.peakBytes),
                      formatNumber("%.3f", s.peakBytes / kGoalBytes), "", "", "", "", "", ""});
    t.data["rows"].push_back({{"step", s.name}, {"seconds", s.seconds}, {"peak_resident_bytes", s.peakBytes}});
  }
  struct Frames {
    bool culling;
    gpu::SampleCounter counter;
    const char* name;
  };
  const std::string noBufferCounter = gpu::sampleCounterProblem(gl, gpu::SampleCounter::Buffer);
  int step = 3;
  for (const Frames& mode : {Frames{false, gpu::SampleCounter::Queries, "no culling"},
                             Frames{true, gpu::SampleCounter::Queries, "paper culling"},
                             Frames{true, gpu::SampleCounter::Buffer, "paper culling, counted in one draw"}}) {
    progress.update(step++, std::string("frames, ") + mode.name);
    const std::string label = std::string("frames: ") + std::to_string(scene.path.frames) + " of an orbit at " +
                              std::to_string(scene.camera.width) + "^2, " + mode.name;
    if (mode.counter == gpu::SampleCounter::Buffer && !noBufferCounter.empty()) {
      t.rows.push_back({label, "not run: " + noBufferCounter, "", "", "", "", "", "", "", ""});
      continue;
    }
    IsoScene run = scene;
    run.occlusionCulling = mode.culling;
    resetPeakResident();
    t0 = Clock::now();
    auto file = std::make_shared<io::LebFile>(io::openLebFile(streamPath));
    ref::CompressedGridField field(std::shared_ptr<const ref::LebStream>(file, &file->stream), kPageCacheBytes);
    const ref::TieredDiamondBounds bounds(coarse, field);
    IsoRunOptions options;
    options.threads = o.threads;
    options.counter = mode.counter;
    const std::vector<IsoFrame> frames = runIsoFrames(gl, run, field, bounds, options);
    const double seconds = secondsSince(t0), peak = peakResidentBytes();
    const IsoFrameAverages a = averageIsoFrames(frames);
    t.rows.push_back({label, formatNumber("%.1f", seconds), bytesText(peak), formatNumber("%.3f", peak / kGoalBytes),
                      formatNumber("%.3f s (", a.frameSeconds) + formatNumber("%.3f / ", a.queries) +
                          formatNumber("%.3f / ", a.refine) + formatNumber("%.3f / ", a.extract) +
                          formatNumber("%.3f)", a.gl),
                      formatNumber("%.0f", a.triangles), formatNumber("%.0f", a.culled), std::to_string(a.falseCulls),
                      std::to_string(frames.empty() ? 0 : frames.back().pagesDecoded), formatNumber("%.3f", a.embree)});
    t.data["rows"].push_back({{"step", label},
                              {"sample_counter", gpu::name(mode.counter)},
                              {"seconds", seconds},
                              {"peak_resident_bytes", peak},
                              {"frame_seconds", a.frameSeconds},
                              {"queries_seconds", a.queries},
                              {"refine_seconds", a.refine},
                              {"extract_seconds", a.extract},
                              {"gl_seconds", a.gl},
                              {"embree_seconds", a.embree},
                              {"triangles", a.triangles},
                              {"culled", a.culled},
                              {"false_culls", a.falseCulls},
                              {"pages_decoded", frames.empty() ? 0 : frames.back().pagesDecoded},
                              {"pages_in_stream", 2 * file->stream.pageCount()}});
  }
  progress.finish();
  std::filesystem::remove(streamPath);
  std::filesystem::remove(dir);
  t.notes =
      "The paper's 1024^3 buckyball as the 1025^3 points of a grid cube (the 1024^3 cells of the grid of k = 10: no "
      "padding). Peak RSS is each step's own: the encoder's VmHWM as a process of its own (polled), and this "
      "process's VmHWM reset before the bounds and before each run of frames (/proc/self/clear_refs), so it includes "
      "the executable, its libraries and the GL context. The bounds are tiered (reference/iso/tiered_bounds.h): a "
      "table of the diamonds of scale 2 and coarser, " +
      bytesText(tableBytes) +
      ", the finest computed from the stream where refinement asks (the same numbers as the full table, which "
      "would be 8 bytes for each of the grid's points). The frames decode pages on demand through a " +
      bytesText(static_cast<double>(kPageCacheBytes)) +
      " page cache; frame time = occlusion queries + refinement + extraction + GL drawing (llvmpipe), the Embree "
      "ground truth of each frame (which judges the culls: false culls are culled diamonds the Embree item buffer "
      "shows visible) apart. 'counted in one draw': the paper's culling with each frame's boxes counted in a storage "
      "buffer in one draw instead of a query and a draw each (gpu/iso_gl.h, SampleCounter). Stream " +
      bytesText(streamBytes) + ". " + (o.quick ? "Quick mode: 65^3, 2 frames at 64^2." : "");
  return t;
}

}  // namespace voxref::conf
