#include "conformance/bench/timevarying_bench.h"
#include "conformance/framework/selection.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

#include "conformance/bench/baselines.h"
#include "conformance/bench/study.h"
#include "conformance/framework/progress.h"
#include "conformance/modules/catalog.h"
#include "conformance/modules/timevarying/fetch_classification.h"
#include "emulation/timevarying_emu.h"
#include "gpu/gl_error.h"
#include "gpu/timevarying_gl.h"
#include "reference/common/parallel.h"
#include "reference/timevarying/plume.h"

namespace voxref::conf {
namespace {

using Clock = std::chrono::steady_clock;

struct Dataset {
  double sparseness;
  double achieved;
  ref::TimeSeries series;
};

// The three plumes of Table 1 (99.92 %, 99.65 %, 99.51 % zero voxels), made once per run.
const std::vector<Dataset>& plumes(const BenchOptions& o) {
  static std::map<bool, std::vector<Dataset>> cache;
  auto& v = cache[o.quick];
  if (v.empty())
    for (double target : {0.9992, 0.9965, 0.9951}) {
      Dataset d{target, 0.0, {}};
      d.series = ref::dischargePlumeWithSparseness({o.quick ? 32 : 128, o.quick ? 8 : 36}, target, &d.achieved);
      v.push_back(std::move(d));
    }
  return v;
}

std::string concat(const ref::TimeSeries& s) {
  std::string bytes;
  for (const auto& step : s.steps) bytes.append(reinterpret_cast<const char*>(step.data()), step.size());
  return bytes;
}

BenchTable table2(const BenchOptions& o) {
  BenchTable t;
  t.id = "timevarying.table2";
  t.title = "Time-varying volumes, Table 2: compression of the synthetic discharge plume (" +
            std::string(o.quick ? "8 steps of 32^3" : "36 steps of 128^3") + ")";
  t.columns = {"data set (sparseness)",
               "level",
               "index bytes",
               "refinement bytes",
               "ratio vs 4 B/voxel",
               "ratio vs 1 B/voxel",
               "blocks",
               "hash hits",
               "collisions",
               "encode MB/s",
               "paper: index",
               "paper: refinement",
               "paper: ratio"};
  // Table 2 of the paper (data sets 1-3, levels 3-5).
  const char* paper[3][3][3] = {
      {{"73728", "5160960", "57.69"}, {"589824", "1374208", "153.76"}, {"4718592", "452864", "58.39"}},
      {{"73728", "22396928", "13.43"}, {"589824", "5451776", "49.98"}, {"4718592", "2472704", "41.99"}},
      {{"73728", "42336256", "7.12"}, {"589824", "7036928", "39.59"}, {"4718592", "3265536", "37.82"}}};
  const ref::TransferFunction tf = ref::transferFunction("plume");
  int d = 0;
  for (const Dataset& ds : plumes(o)) {
    ++d;
    for (int level = 3; level <= 5; ++level) {
      if (o.quick && level > 3) break;
      ref::TimeVaryingTextures tex;
      const Timing enc = measureOnce([&] { tex = ref::encodeTimeVarying(ds.series, tf, {level}); });
      const auto& st = tex.stats;
      const double mb = static_cast<double>(st.inputVoxels) / 1e6;
      t.rows.push_back({std::to_string(d) + " (" + formatNumber("%.2f %%", 100 * ds.achieved) + ")",
                        std::to_string(level), std::to_string(st.indexBytes), std::to_string(st.refinementBytes),
                        formatNumber("%.2f:1", st.ratioAgainst4Bytes()), formatNumber("%.2f:1", st.ratioAgainst1Byte()),
                        std::to_string(st.distinctBlocks), std::to_string(st.hashHits),
                        std::to_string(st.hashCollisions), formatNumber("%.0f", mb / enc.median),
                        o.quick ? "" : paper[d - 1][level - 3][0], o.quick ? "" : paper[d - 1][level - 3][1],
                        o.quick ? "" : std::string(paper[d - 1][level - 3][2]) + ":1"});
      t.data["rows"].push_back({{"data_set", d},
                                {"sparseness", ds.achieved},
                                {"level", level},
                                {"index_bytes", st.indexBytes},
                                {"refinement_bytes", st.refinementBytes},
                                {"ratio_4_bytes", st.ratioAgainst4Bytes()},
                                {"ratio_1_byte", st.ratioAgainst1Byte()},
                                {"distinct_blocks", st.distinctBlocks},
                                {"hash_hits", st.hashHits},
                                {"hash_collisions", st.hashCollisions},
                                {"encode", toJson(enc)}});
    }
    // The general-purpose baseline on the same bytes: zstd on the raw time steps, one frame.
    const std::string raw = concat(ds.series);
    for (int zl : {3, 19}) {
      if (o.quick && zl == 19) continue;
      const BaselineResult b = zstdBaseline(raw, zl);
      const std::size_t size = b.bytes;
      const Timing& z = b.compress;
      t.rows.push_back({std::to_string(d) + " (" + formatNumber("%.2f %%", 100 * ds.achieved) + ")",
                        "zstd -" + std::to_string(zl), "-", std::to_string(size) + " (raw uint8)",
                        formatNumber("%.2f:1", 4.0 * raw.size() / size),
                        formatNumber("%.2f:1", double(raw.size()) / size), "-", "-", "-",
                        formatNumber("%.0f", raw.size() / 1e6 / z.median), "", "", ""});
      t.data["baselines"].push_back(
          {{"data_set", d}, {"codec", "zstd -" + std::to_string(zl)}, {"bytes", size}, {"seconds", z.median}});
    }
  }
  t.notes =
      "Index and refinement bytes count the used texels at 4 bytes (the paper's 'cells' are bytes: 36 x 16^3 x 4 = "
      "589,824 at level 4), "
      "ratios are against 4 bytes (the paper's) and 1 byte per voxel. The synthetic plume "
      "(reference/timevarying/plume.h) is "
      "calibrated to the paper's sparseness; its coherence differs from the OOC simulations, so compare the shape "
      "(level 4 best, "
      "ratio falling with sparseness), not the numbers. zstd compresses the raw uint8 steps (no transfer function), so "
      "its "
      "'ratio vs 4 B' is what it would give against RGBA; it is not randomly accessible in a shader. Encode MB/s: "
      "input voxels per second.";
  return t;
}

BenchTable table3(const BenchOptions& o, gpu::Context& gl, const emu::PrecisionProfile* profile) {
  BenchTable t;
  t.id = "timevarying.table3";
  t.title =
      "Time-varying volumes, Table 3: frames per second (data set 3, level 4, paper decoder, back-to-front slices into "
      "rgba8)";
  t.columns = {"slices", "image", "GL fps", "emulation fps", "paper fps (ATI 9700 Pro)"};
  const Dataset& ds = plumes(o)[2];
  const ref::TimeVaryingTextures tex =
      ref::encodeTimeVarying(ds.series, ref::transferFunction("plume"), {o.quick ? 3 : 4});
  const std::pair<int, int> configs[] = {{200, 128}, {200, 256}, {200, 512}, {500, 128}, {500, 256}, {500, 512}};
  const char* paper[] = {"33.76", "8.65", "4.23", "14.66", "4.00", "1.30"};
  Progress progress("voxref bench: table 3", 6);
  int i = 0;
  for (const auto& [slices, size] : configs) {
    progress.update(i, std::to_string(slices) + " slices, " + std::to_string(size) + "^2");
    const int s = o.quick ? size / 8 : size, p = o.quick ? slices / 10 : slices;
    const ref::PlaneFrame frame = ref::orbitFrame(30.0, 20.0, s, s, p);
    const int step = ds.series.steps.size() > 1 ? static_cast<int>(ds.series.steps.size()) - 1 : 0;
    const Timing g = measureOnce([&] { (void)gpu::compositeGl(gl, tex, ref::DecoderVariant::Paper, step, frame); });
    Timing e{};
    if (profile)
      e = measureOnce(
          [&] { (void)emu::emulateComposite(tex, ref::DecoderVariant::Paper, step, frame, *profile, o.threads); });
    t.rows.push_back({std::to_string(p), std::to_string(s) + "^2", formatNumber("%.2f", 1.0 / g.median),
                      profile ? formatNumber("%.2f", 1.0 / e.median) : "n/a", o.quick ? "" : paper[i]});
    t.data["rows"].push_back({{"slices", p}, {"image", s}, {"gl", toJson(g)}, {"emulation", toJson(e)}});
    ++i;
  }
  progress.finish();
  t.notes =
      "One frame each (decoding and compositing all slices, read-back included). Slices are full-screen passes that "
      "discard "
      "fragments outside the volume; the paper drew slice polygons clipped to it. GL: " +
      gl.info().renderer + "; emulation on " + std::to_string(ref::workerCount(o.threads)) + " thread(s).";
  return t;
}

// One variant's wrong fetches as the study's error: the share of samples that read another block or
// voxel than floor(p * side), with every count in the figures.
StudyVariant fetchVariant(const std::string& name, const FetchCounts& c, const ref::TimeVaryingTextures& tex) {
  StudyVariant v;
  v.name = name;
  v.error = c.samples ? static_cast<double>(c.wrong()) / static_cast<double>(c.samples)
                      : std::numeric_limits<double>::quiet_NaN();
  if (!c.samples) v.missing = "no sample inside the volume";
  v.figures = c.toJson();
  v.figures.erase("examples");
  v.memoryBytes = static_cast<double>(tex.stats.indexBytes + tex.stats.refinementBytes);
  return v;
}

BenchTable study(const BenchOptions& o, gpu::Context& gl, const emu::PrecisionProfile* /*measured on GL instead*/) {
  const Dataset& ds = plumes(o)[1];
  const ref::TransferFunction tf = ref::transferFunction("plume");
  const int level = o.quick ? 3 : 4;
  struct V {
    const char* name;
    ref::DecoderVariant decoder;
    ref::IndexEncoding encoding;
  };
  const V variants[] = {
      {"paper / rgba8 (the paper's)", ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedRgba8},
      {"paper / rgba16", ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedRgba16},
      {"paper / float", ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedFloat},
      {"texel_centre / rgba8 block numbers", ref::DecoderVariant::TexelCentre, ref::IndexEncoding::BlockRgba8},
      {"texel_fetch / rgba8 block numbers", ref::DecoderVariant::TexelFetch, ref::IndexEncoding::BlockRgba8}};
  const int n = o.quick ? 32 : 128;
  const ref::PlaneFrame frame = ref::orbitFrame(30.0, 20.0, n, n, n);
  const int step = static_cast<int>(ds.series.steps.size()) - 1;
  const std::string error = "share of fetches that read another block or voxel than floor(p * side)";
  const std::string memory = "index + refinement texels in use";
  // The fetches of the first group are measured on GL (gpu::measureFetchesGl, the address
  // textures), so every driver gets its error figure; the second group's are the emulations'.
  Progress progress("voxref bench study.timevarying", 5 + static_cast<long>(emu::knownProfiles().size()));
  long done = 0;
  StudyGroup address{"decoder and index encoding",
                     error,
                     "GL decode of an orbit frame on " + gl.info().renderer + ", read-back included",
                     memory,
                     false,
                     {},
                     ""};
  for (const V& v : variants) {
    progress.update(done++, v.name);
    const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(ds.series, tf, {level, v.encoding});
    ref::RgbaStack colours;
    const Timing g = measure([&] { colours = gpu::decodePlanesGl(gl, tex, v.decoder, step, frame); }, kStudyRuns);
    const ref::MeasuredFetches fetched = gpu::measureFetchesGl(gl, tex, v.decoder, step, frame);
    StudyVariant sv =
        fetchVariant(v.name, classifyFetches(tex, ds.series, tf, step, frame, fetched.fetches, colours.colours), tex);
    sv.time = g;
    address.variants.push_back(sv);
  }
  StudyGroup profiles{
      "fmod addressing per profile (paper decoder, rgba8 index)",
      error,
      "emulated decode of the orbit frame (CPU, " + std::to_string(ref::workerCount(o.threads)) + " thread(s))",
      memory,
      false,
      {},
      "The other drivers' arithmetic (fused or unfused multiply-add, repeat scaling, denormals) through their "
      "emulations; times are the emulator's."};
  const ref::TimeVaryingTextures paper =
      ref::encodeTimeVarying(ds.series, tf, {level, ref::IndexEncoding::NormalizedRgba8});
  for (const emu::PrecisionProfile& p : emu::knownProfiles()) {
    progress.update(done++, std::string(p.name));
    emu::EmulatedDecode decoded;
    const Timing e = measure(
        [&] { decoded = emu::emulateDecodePlanes(paper, ref::DecoderVariant::Paper, step, frame, p, o.threads); },
        kStudyRuns);
    StudyVariant sv = fetchVariant(
        std::string(p.name),
        classifyFetches(paper, ds.series, tf, step, frame, emu::fetchesOf(decoded), decoded.colours.colours), paper);
    sv.time = e;
    profiles.variants.push_back(sv);
  }
  progress.finish();
  return studyTable("study.timevarying",
                    "Study, time-varying volumes (plume data set 2, level " + std::to_string(level) + ", orbit frame " +
                        std::to_string(n) + "^2 x " + std::to_string(n) + " samples, last time step)",
                    {address, profiles},
                    "A fetch is wrong when it reads another voxel or block than floor(p * side) "
                    "(fetch_classification.h); the decoded "
                    "colour of a wrong fetch may still be right (figures: wrong_colour).");
}

}  // namespace

std::vector<std::string> timeVaryingBenchIds() {
  return {"timevarying.table2", "timevarying.table3", "study.timevarying"};
}

std::vector<BenchTable> timeVaryingBench(const BenchOptions& o, gpu::Context& gl,
                                         const emu::PrecisionProfile* profile) {
  std::vector<BenchTable> tables;
  if (globMatch(o.filter, "timevarying.table2")) tables.push_back(table2(o));
  if (globMatch(o.filter, "timevarying.table3")) tables.push_back(table3(o, gl, profile));
  if (globMatch(o.filter, "study.timevarying")) tables.push_back(study(o, gl, profile));
  return tables;
}

}  // namespace voxref::conf
