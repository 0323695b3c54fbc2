#include "conformance/bench/leb_scale_bench.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <stdexcept>

#include "conformance/bench/processes.h"
#include "conformance/bench/study.h"
#include "conformance/framework/progress.h"
#include "conformance/io/atomic_file.h"
#include "conformance/io/leb_file_codec.h"
#include "conformance/io/mapped_file.h"
#include "reference/leb/gradients.h"
#include "reference/leb/leb_grid.h"
#include "reference/leb/leb_padding.h"

namespace voxref::conf {
namespace {

// A smooth field plus noise (uint8), x fastest, written slice by slice: the kind of volume whose
// deltas are small but not zero (the "synthetic smooth field + noise").
void writeSmoothNoise(const std::filesystem::path& path, const ref::Dims3& d, unsigned seed) {
  std::ofstream out(path, std::ios::binary);
  std::mt19937 rng(seed);
  std::string slice(static_cast<std::size_t>(d[0]) * static_cast<std::size_t>(d[1]), '\0');
  for (int z = 0; z < d[2]; ++z) {
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) {
        const double f =
            127.5 + 90.0 * std::sin(0.031 * x + 0.5 * std::cos(0.023 * y)) * std::cos(0.027 * z - 0.017 * y);
        const double v = std::round(f) + static_cast<double>(rng() % 9) - 4.0;
        slice[static_cast<std::size_t>(x) + static_cast<std::size_t>(d[0]) * static_cast<std::size_t>(y)] =
            static_cast<char>(std::clamp(v, 0.0, 255.0));
      }
    out.write(slice.data(), static_cast<std::streamsize>(slice.size()));
  }
  if (!out) throw std::runtime_error("cannot write " + path.string() + " for the LEB scale bench");
}

bool sameBytes(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::ifstream x(a, std::ios::binary), y(b, std::ios::binary);
  std::string p(1 << 20, '\0'), q(1 << 20, '\0');
  while (x && y) {
    x.read(p.data(), static_cast<std::streamsize>(p.size()));
    y.read(q.data(), static_cast<std::streamsize>(q.size()));
    if (x.gcount() != y.gcount() || std::memcmp(p.data(), q.data(), static_cast<std::size_t>(x.gcount())) != 0)
      return false;
  }
  return x.eof() && y.eof();
}

// Whether `decoded` holds the gradients of the uint8 volume `raw` (quantizedGradients), computed
// here slice by slice from a mapping of the volume (trimmed as it goes), so the check itself never
// holds the volume.
bool gradientsMatch(const std::filesystem::path& raw, const ref::Dims3& d, const std::filesystem::path& decoded) {
  io::MappedFile volume = io::MappedFile::openRead(raw), grads = io::MappedFile::openRead(decoded);
  const std::size_t slice = 3 * static_cast<std::size_t>(d[0]) * static_cast<std::size_t>(d[1]);
  if (grads.size() != slice * static_cast<std::size_t>(d[2])) return false;
  std::vector<std::int8_t> expected(slice);
  for (int z = 0; z < d[2]; ++z) {
    ref::quantizedGradientSlice(volume.data(), d, z, expected.data());
    if (std::memcmp(expected.data(), grads.data() + slice * static_cast<std::size_t>(z), slice) != 0) return false;
    if (z % 64 == 63) {
      volume.trim();
      grads.trim();
    }
  }
  return true;
}

// The columns of both tables, and the idle row (the executable and its libraries, doing nothing).
BenchTable scaleTable(const std::string& id, const std::string& title, ProcessRun& idle) {
  BenchTable t;
  t.id = id;
  t.title = title;
  t.columns = {"volume",
               "step",
               "seconds",
               "peak RSS",
               "above an idle voxref",
               "bytes per sample (above idle)",
               "M samples/s",
               "stream bytes",
               "peak RSS / 2 GB goal"};
  idle = runVoxref({"--version"});
  t.data["idle_peak_resident_bytes"] = idle.peakBytes;
  t.rows.push_back({"none (idle: voxref --version)", "start and exit", formatNumber("%.3f", idle.seconds),
                    bytesText(idle.peakBytes), "", "", "", "", ""});
  t.data["volumes"] = nlohmann::json::array();
  return t;
}

// One volume of the smooth field + noise: written, encoded and decoded (each step a process of its
// own), the round trip checked bit for bit, a row per step and the figures in t.data["volumes"]; the
// files removed after.
void measureVolume(BenchTable& t, const std::filesystem::path& dir, const ref::Dims3& d, const ProcessRun& idle) {
  const std::string name = ref::dimsText(d);
  const std::filesystem::path raw = dir / (name + ".raw"), stream = dir / (name + ".vxleb"),
                              back = dir / (name + ".decoded.raw"), grads = dir / (name + ".grad");
  writeSmoothNoise(raw, d, 18);
  const std::vector<std::string> dims = {std::to_string(d[0]), std::to_string(d[1]), std::to_string(d[2])};
  const ProcessRun enc = runVoxref({"encode", "--codec", "leb", "--input", raw.string(), "--dims", dims[0], dims[1],
                                    dims[2], "--out", stream.string()});
  const ProcessRun dec = runVoxref({"decode", "--codec", "leb", "--input", stream.string(), "--out", back.string(),
                                    "--gradients-out", grads.string()});
  if (!sameBytes(raw, back)) throw std::runtime_error("the LEB round trip of " + name + " is not bit for bit");
  if (!gradientsMatch(raw, d, grads))
    throw std::runtime_error("the decoded gradients of " + name + " are not the volume's gradients");
  const double samples = static_cast<double>(d[0]) * d[1] * d[2];
  const double streamBytes = static_cast<double>(std::filesystem::file_size(stream));
  for (const auto& [step, run] : {std::pair<const char*, const ProcessRun&>{"encode", enc}, {"decode", dec}}) {
    const double above = std::max(0.0, run.peakBytes - idle.peakBytes);
    t.rows.push_back({name + " uint8, smooth field + noise, gradients", step, formatNumber("%.3f", run.seconds),
                      bytesText(run.peakBytes), bytesText(above), formatNumber("%.1f", above / samples),
                      formatNumber("%.3g", samples / 1e6 / run.seconds), formatNumber("%.0f", streamBytes),
                      formatNumber("%.3f", run.peakBytes / 2e9)});
  }
  t.data["volumes"].push_back({{"dims", {d[0], d[1], d[2]}},
                               {"samples", samples},
                               {"stream_bytes", streamBytes},
                               {"round_trip", "bit for bit, data and gradients"},
                               {"encode", {{"seconds", enc.seconds}, {"peak_resident_bytes", enc.peakBytes}}},
                               {"decode", {{"seconds", dec.seconds}, {"peak_resident_bytes", dec.peakBytes}}}});
  for (const auto& p : {raw, stream, back, grads}) std::filesystem::remove(p);
}

}  // namespace

BenchTable lebScaleBench(const BenchOptions& o) {
  ProcessRun idle;
  BenchTable t = scaleTable(
      kLebScaleBenchId, "LEB at scale: encode and decode in processes of their own (time, peak resident memory)", idle);
  const std::filesystem::path dir = o.out / "leb-scale";
  io::ensureDirectory(dir);
  const std::vector<ref::Dims3> volumes =
      o.quick ? std::vector<ref::Dims3>{{1025, 1, 1}, {128, 128, 128}}
              : std::vector<ref::Dims3>{{1025, 1, 1}, {512, 512, 512}, {1024, 1024, 1024}};
  Progress progress("voxref bench leb.scale", static_cast<long>(volumes.size()));
  long done = 0;
  for (const ref::Dims3& d : volumes) {
    progress.update(done++, ref::dimsText(d));
    measureVolume(t, dir, d, idle);
  }
  progress.finish();
  std::filesystem::remove(dir);
  // The paper's largest volume, 2048x2048x1920 (Gregorski et al. 2004, section 5), on paper: time
  // in proportion to the samples of the largest volume measured here; resident memory its peak
  // plus the larger tables of the shell of padding (leb_padding.h, a closed form of the extents);
  // disk the volume (1 byte a sample), the encoder's gradients file (3), the stream (this run's
  // bytes per sample) and the decoded volume and gradients (4).
  if (!t.data["volumes"].empty()) {
    const nlohmann::json& big = t.data["volumes"].back();
    const ref::Dims3 measured{big["dims"][0].get<int>(), big["dims"][1].get<int>(), big["dims"][2].get<int>()};
    const ref::Dims3 paper{2048, 2048, 1920};
    const double scale = static_cast<double>(ref::sampleCount(paper)) / big["samples"].get<double>();
    const double shellGrowth =
        static_cast<double>(ref::LebPadding::tableBytes(ref::LebGrid{11}, paper)) -
        static_cast<double>(ref::LebPadding::tableBytes(ref::lebGridCovering(measured), measured));
    const double samples = static_cast<double>(ref::sampleCount(paper));
    const double streamPerSample = big["stream_bytes"].get<double>() / big["samples"].get<double>();
    nlohmann::json estimate = {{"dims", {2048, 2048, 1920}}, {"from", ref::dimsText(measured)}};
    // The shells' tables each step holds: the encoder one channel's at a time, the decoder both.
    for (const auto& [step, tables] : {std::pair<const char*, double>{"encode", 1.0}, {"decode", 2.0}}) {
      const double seconds = big[step]["seconds"].get<double>() * scale;
      const double peak = big[step]["peak_resident_bytes"].get<double>() + shellGrowth * tables;
      const double disk = 4.0 * samples + streamPerSample * samples;
      estimate[step] = {{"seconds", seconds}, {"peak_resident_bytes", peak}, {"disk_bytes", disk}};
      t.rows.push_back({"2048x2048x1920 (the paper's; estimated from " + ref::dimsText(measured) + ")", step,
                        formatNumber("%.0f", seconds), bytesText(peak), "", "", "",
                        formatNumber("%.3g", streamPerSample * samples), formatNumber("%.3f", peak / 2e9)});
    }
    t.data["estimate_2048x2048x1920"] = estimate;
  }
  t.notes =
      "Each step is `voxref encode --codec leb` or `voxref decode --codec leb` (with --gradients-out) run as a process "
      "of its own; seconds are its wall time, peak RSS its VmHWM (polled every 5 ms from /proc), which includes "
      "the executable and its libraries (the idle row: `voxref --version`) and every page of the mapped files "
      "(volume, gradients, stream) while it is mapped; 'above an idle voxref' subtracts the idle peak. Both steps "
      "stream between files (conformance/io/leb_file_codec.h): the mappings are trimmed whenever the resident "
      "memory exceeds a window of " +
      bytesText(static_cast<double>(io::kLebWindowBytes)) +
      ", so the peak is the window, the shell of padding and a batch of pages, not the volume. The decoded "
      "samples are compared with the input bit for bit, and the decoded gradients with the input's gradients "
      "made slice by slice. The 1025x1x1 volume sits in a 1025^3 grid: with the padding "
      "shell (reference/leb/leb_padding.h) and only the pages of the volume stored (reference/leb/FORMAT.md, version "
      "2) it costs what its samples cost. The 2048x2048x1920 rows are estimates, not runs: seconds scaled by the "
      "samples from the largest volume measured, peak RSS that volume's plus the larger tables of the shell of "
      "padding (LebPadding::tableBytes: the encoder holds one channel's, the decoder both), disk the volume, gradients "
      "and stream (encode: input, gradients scratch and stream; "
      "decode: stream, volume and gradients). `voxref bench --filter leb.paper_scale` runs that volume (the grid of "
      "k = 11, 2049^3) the same way; it runs only when named, for its hours and 70 GB of scratch disk. " +
      std::string(o.quick ? "Quick mode: 128^3 instead of 512^3 and 1024^3." : "");
  return t;
}

BenchTable lebPaperScaleBench(const BenchOptions& o) {
  const ref::Dims3 paper{2048, 2048, 1920};
  const std::filesystem::path dir = o.out / "leb-paper-scale";
  io::ensureDirectory(dir);
  // The disk the run needs at its fullest (decoding: the input kept for the check, the stream, the
  // decoded volume and gradients), the stream at the 1024^3 run's 3.6 bytes a sample of this field:
  // refused before anything is written when the output folder's file system lacks it.
  const double samples = static_cast<double>(ref::sampleCount(paper));
  const double needed = samples * (1.0 + 3.6 + 4.0);
  const double available = static_cast<double>(std::filesystem::space(dir).available);
  if (available < needed)
    throw std::runtime_error("leb.paper_scale needs about " + bytesText(needed) + " free in " + dir.string() +
                             " (the volume, its stream, and the decoded volume and gradients); it has " +
                             bytesText(available));
  ProcessRun idle;
  BenchTable t =
      scaleTable(kLebPaperScaleBenchId,
                 "LEB at the paper's largest size, 2048x2048x1920 (Gregorski et al. 2004, section 5): encode "
                 "and decode in processes of their own",
                 idle);
  Progress progress("voxref bench leb.paper_scale", 1);
  progress.update(0, ref::dimsText(paper));
  measureVolume(t, dir, paper, idle);
  progress.finish();
  std::filesystem::remove(dir);
  t.notes =
      "The paper's largest volume (a 2048x2048x1920 simulation, compressed and decompressed on a 2004 PC) as "
      "voxref's smooth field + noise of leb.scale, in the grid of k = 11 (2049^3 points; reference/leb/FORMAT.md). "
      "Each step is `voxref encode --codec leb` or `voxref decode --codec leb` (with --gradients-out) in a "
      "process of its own, streaming between files in a resident window of " +
      bytesText(static_cast<double>(io::kLebWindowBytes)) +
      "; peak RSS is its VmHWM, mapped file pages included. The decoded samples are compared with the input "
      "bit for bit, and the decoded gradients with the input's gradients made slice by slice. Runs only when "
      "named (--filter leb.paper_scale): its encode takes about 35 minutes on 2 cores and its decode about 18 "
      "(docs/leb.md, 'Streaming between files'); it needs " +
      bytesText(needed) + " of scratch disk in the output folder, removed after.";
  return t;
}

}  // namespace voxref::conf
