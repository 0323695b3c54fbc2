// Writes the seed corpora of valid inputs for the fuzz targets of tests/fuzz (all but the LEB
// stream's, which make_leb_seeds writes), with the current writers of the product, so that the
// seeds follow the formats as they change:
//
//   make_fuzz_seeds timevarying DIR   .vxtv containers (serializeTimeVarying of encoded series)
//   make_fuzz_seeds huffman DIR       lead-1 code tables with a page each, and symbol counts
//   make_fuzz_seeds adaptive_page DIR pages of the adaptive delta coder, every shape
//   make_fuzz_seeds context_page DIR  pages of the context coder of small volumes, samples and gradients
//   (context_page_input.h) make_fuzz_seeds scene DIR         scene JSON: the built-in cases' scenes and the iso scenes
//   make_fuzz_seeds raw_volume DIR    raw volumes, plain and gzip (the target's input layout)
//   make_fuzz_seeds manifest DIR      fixture manifests (the layout generateIsoFixtures writes)
//   make_fuzz_seeds results DIR       results.json files (resultsJson)
//   make_fuzz_seeds expectations DIR  fails, flakes and skips files and case lists (docs/ci.md)
//
// Every seed is read back with the product's own reader before it is written: a seed the reader
// refuses fails the seeds test (exit 1), since a corpus of invalid files would only fuzz the
// first checks.
#include <zlib.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "conformance/framework/expectations/expectation_files.h"
#include "conformance/framework/report/results_json.h"
#include "conformance/framework/report/results_reader.h"
#include "conformance/framework/suite/suite_file.h"
#include "conformance/io/raw_volume.h"
#include "conformance/io/sha256.h"
#include "conformance/modules/catalog.h"
#include "conformance/modules/iso/iso_fixtures.h"
#include "conformance/modules/iso/iso_manifest.h"
#include "conformance/modules/iso/iso_scene.h"
#include "conformance/modules/sparsegrid/sparsegrid_scene.h"
#include "conformance/modules/timevarying/timevarying_scene.h"
#include "reference/common/byte_stream.h"
#include "reference/leb/adaptive_delta_coder.h"
#include "reference/leb/context_gradient_coder.h"
#include "reference/leb/context_value_coder.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/lead1_coder.h"
#include "reference/leb/leb_padding.h"
#include "reference/timevarying/container.h"
#include "reference/timevarying/plume.h"
#include "tests/fuzz/context_page_input.h"

namespace {

using namespace voxref;
namespace fs = std::filesystem;

fs::path outDir;

void write(const std::string& name, const std::string& bytes) {
  std::ofstream out(outDir / name, std::ios::binary | std::ios::trunc);
  out << bytes;
  if (!out) throw std::runtime_error("cannot write " + (outDir / name).string());
}

// --- time-varying containers ---------------------------------------------------------------
void timevarying() {
  struct Seed {
    std::string name;
    ref::TimeSeries series;
    std::string transfer;
    int level;
    ref::IndexEncoding encoding;
    ref::AlphaOnePolicy alphaOne;
  };
  std::vector<ref::Volume<std::uint8_t>> odd;  // 5x6x7, padded to 8^3
  for (int t = 0; t < 2; ++t) {
    ref::Volume<std::uint8_t> v({5, 6, 7});
    for (std::size_t i = 0; i < v.data().size(); ++i)
      v.data()[i] = static_cast<std::uint8_t>((i * 7 + 40 * t) % 97 < 40 ? 0 : 200);
    odd.push_back(std::move(v));
  }
  std::vector<Seed> seeds{
      {"plume8_rgba8_l1.vxtv", ref::dischargePlume({8, 2, 4000.0}), "gray", 1, ref::IndexEncoding::NormalizedRgba8,
       ref::AlphaOnePolicy::Refine},
      {"plume8_rgba16_l2.vxtv", ref::dischargePlume({8, 2, 4000.0}), "gray", 2, ref::IndexEncoding::NormalizedRgba16,
       ref::AlphaOnePolicy::Refine},
      {"blobs8_float_l1.vxtv", ref::driftingBlobs(8, 3), "gray", 1, ref::IndexEncoding::NormalizedFloat,
       ref::AlphaOnePolicy::Refine},
      {"blobs8_block_l2.vxtv", ref::driftingBlobs(8, 3), "gray", 2, ref::IndexEncoding::BlockRgba8,
       ref::AlphaOnePolicy::Paper},
      {"odd5x6x7_rgba8_l1.vxtv", ref::padToCube(odd), "gray", 1, ref::IndexEncoding::NormalizedRgba8,
       ref::AlphaOnePolicy::Refine},
  };
  for (const std::string& tf : ref::transferFunctionNames())
    if (tf != "gray") {
      seeds.push_back({"blobs8_" + tf + "_l1.vxtv", ref::driftingBlobs(8, 2), tf, 1,
                       ref::IndexEncoding::NormalizedRgba8, ref::AlphaOnePolicy::Paper});
      break;
    }
  for (const Seed& s : seeds) {
    ref::TimeVaryingOptions o;
    o.level = s.level;
    o.encoding = s.encoding;
    o.alphaOne = s.alphaOne;
    ref::TimeVaryingFile f;
    f.transfer = ref::transferFunction(s.transfer);
    f.textures = ref::encodeTimeVarying(s.series, f.transfer, o);
    const std::string bytes = ref::serializeTimeVarying(f);
    (void)ref::parseTimeVarying(bytes);
    write(s.name, bytes);
  }
}

// --- lead-1 code tables and pages ----------------------------------------------------------
void huffman() {
  auto seed = [](const std::string& name, int bits, const std::vector<std::vector<std::int32_t>>& pages) {
    ref::Lead1Counter counter(bits);
    for (const auto& p : pages) counter.add(p);
    const ref::Lead1Code code = counter.code();
    if (!ref::lead1CodeProblem(code).empty()) throw std::runtime_error(name + ": " + ref::lead1CodeProblem(code));
    ref::BitWriter w;
    ref::Lead1Encoder(code).encodePage(pages.front(), w);
    std::string bytes(1, static_cast<char>(bits == 16 ? 1 : 0));
    bytes.append(code.lengths.begin(), code.lengths.end());
    bytes += w.finish();
    write(name, bytes);
  };
  std::vector<std::int32_t> smooth, noisy, extremes, wide;
  std::uint32_t x = 12345;
  for (int i = 0; i < 200; ++i) {
    smooth.push_back(static_cast<std::int32_t>(std::lround(6 * std::sin(0.3 * i))));
    x = x * 1103515245u + 12345u;
    noisy.push_back(static_cast<std::int32_t>((x >> 16) % 256) - 128);
    wide.push_back(static_cast<std::int32_t>((x >> 8) % 65536) - 32768);
  }
  extremes = {0, -128, 127, 1, -1, 0, 0, -128, 64, -64};
  seed("smooth8.lead1", 8, {smooth});
  seed("noisy8.lead1", 8, {noisy, smooth});
  seed("extremes8.lead1", 8, {extremes});
  seed("wide16.lead1", 16, {wide, {-32768, 32767, 0}});
  seed("constant8.lead1", 8, {std::vector<std::int32_t>(64, 0)});
  // Counts for huffmanCodeLengths: byte 0 = 2 (lengths mode), byte 1 = limit - 1, u16 counts.
  auto counts = [](const std::string& name, int limit, const std::vector<std::uint16_t>& c) {
    std::string bytes{char(2), static_cast<char>(limit - 1)};
    for (std::uint16_t v : c) bytes += std::string{static_cast<char>(v & 0xff), static_cast<char>(v >> 8)};
    write(name, bytes);
  };
  counts("counts9_limit12.counts", 12, {500, 300, 120, 60, 30, 10, 5, 0, 1});
  counts("counts17_limit4.counts", 4, {1, 1, 2, 3, 5, 8, 13, 21, 34, 55, 89, 144, 233, 377, 610, 987, 1597});
  counts("counts1.counts", 12, {0, 0, 7});
}

// --- scene JSON ----------------------------------------------------------------------------
void scene() {
  std::set<std::string> seen;
  std::map<std::string, int> perSystem;
  for (const conf::Case& c : conf::allCases()) {
    if (!c.scene) continue;
    const std::string text = c.scene->dump(2);
    if (!seen.insert(text).second || ++perSystem[c.system] > 12) continue;
    if (c.scene->value("system", std::string("sparsegrid")) == "timevarying")
      (void)conf::parseTimeVaryingScene(*c.scene);
    else
      (void)conf::parseSparseGridScene(*c.scene);
    write(c.id + ".json", text + "\n");
  }
  conf::SparseGridScene explicitCamera;
  explicitCamera.data.volume = "volume.raw.gz";
  explicitCamera.data.volumeDims = {9, 9, 9};
  explicitCamera.camera.origin = glm::dvec3(0.0);
  explicitCamera.camera.dx = glm::dvec3(0.125, 0, 0);
  explicitCamera.camera.dy = glm::dvec3(0, 0.125, 0);
  explicitCamera.camera.dz = glm::dvec3(0, 0, 0.125);
  explicitCamera.passOrder = {1, 0};
  (void)conf::parseSparseGridScene(conf::toJson(explicitCamera));
  write("sparsegrid_explicit_camera.json", conf::toJson(explicitCamera).dump(2) + "\n");
  conf::TimeVaryingScene tv;
  tv.onlySteps = {0, 2};
  tv.frame = "orbit";
  write("timevarying_orbit.json", conf::toJson(tv).dump(2) + "\n");
  std::vector<conf::IsoScene> iso = conf::builtInIsoScenes();
  for (const conf::IsoScene& s : conf::hardIsoScenes()) iso.push_back(s);
  for (const conf::IsoScene& s : iso) {
    (void)conf::isoSceneFromJson(conf::toJson(s));
    write("iso_" + s.name + ".json", conf::toJson(s).dump(2) + "\n");
  }
}

// --- raw volumes: byte 0 = type (bit 0: uint16), 3 x int32 dims, then the file -----------
std::string gzip(const std::string& plain) {
  z_stream z{};
  if (deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw std::runtime_error("deflateInit2");
  std::string out(deflateBound(&z, plain.size()) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(plain.data()));
  z.avail_in = static_cast<uInt>(plain.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  if (deflate(&z, Z_FINISH) != Z_STREAM_END) throw std::runtime_error("deflate");
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

void rawVolume() {
  auto seed = [](const std::string& name, bool sixteen, ref::Dims3 dims, const std::string& file) {
    ref::ByteWriter w;
    w.le<std::uint8_t>(sixteen ? 1 : 0);
    for (int d : dims) w.le<std::uint32_t>(static_cast<std::uint32_t>(d));
    w.bytes(file);
    write(name, w.str());
  };
  std::string u8(4 * 3 * 2, '\0'), u16(3 * 3 * 3 * 2, '\0'), big(16 * 16 * 16, '\0');
  for (std::size_t i = 0; i < u8.size(); ++i) u8[i] = static_cast<char>(i * 11);
  for (std::size_t i = 0; i < u16.size(); ++i) u16[i] = static_cast<char>(i * 37 + 1);
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i % 16 < 8 ? 0 : i / 16);
  seed("u8_4x3x2.raw", false, {4, 3, 2}, u8);
  seed("u16_3x3x3.raw", true, {3, 3, 3}, u16);
  seed("u8_4x3x2.raw.gz", false, {4, 3, 2}, gzip(u8));
  seed("u16_3x3x3.raw.gz", true, {3, 3, 3}, gzip(u16));
  seed("u8_16x16x16.raw.gz", false, {16, 16, 16}, gzip(big));
  seed("u8_1x1x1.raw", false, {1, 1, 1}, std::string(1, '\x7f'));
}

// --- fixture manifests (the layout generateIsoFixtures writes) -----------------------------
void manifest() {
  auto seed = [](const std::string& name, const std::vector<conf::IsoScene>& scenes) {
    nlohmann::json m{{"generator", conf::kFixtureGenerator},
                     {"scenes", nlohmann::json::array()},
                     {"files", nlohmann::json::array()}};
    for (const conf::IsoScene& s : scenes) {
      m["scenes"].push_back(conf::toJson(s));
      for (int f = 0; f < s.path.frames; ++f)
        for (const char* kind : {"_mesh.exr", "_exact.exr"}) {
          const std::string path = s.name + (f < 10 ? "/frame_0" : "/frame_") + std::to_string(f) + kind;
          m["files"].push_back({{"path", path}, {"sha256", io::sha256Hex(path)}});
        }
    }
    const std::string text = m.dump(2) + "\n";
    (void)conf::parseIsoFixtureManifest(text, name);
    write(name, text);
  };
  std::vector<conf::IsoScene> hard = conf::hardIsoScenes();
  for (conf::IsoScene& s : hard) s.path.frames = 2;
  seed("builtin.json", conf::builtInIsoScenes());
  seed("hard.json", hard);
  // Small volumes, so that the fuzz target builds them (it skips volumes above 24^3).
  std::vector<conf::IsoScene> small = hard;
  for (conf::IsoScene& s : small) conf::aimOrbitAt(s, {12, 12, 12});
  seed("hard_small.json", small);
  conf::IsoScene user = conf::builtInIsoScenes().front();  // `fixtures generate --volume`: a user's file
  user.name = "engine";
  user.data.clear();
  user.volumeFile = "/data/engine.raw.gz";
  user.volumeIsUint16 = true;
  conf::aimOrbitAt(user, {64, 64, 32});
  user.path.frames = 1;
  seed("user_volume.json", {user});
  seed("empty.json", {});
}

// --- results.json ----------------------------------------------------------------------------
void results() {
  conf::CaseResult full;
  full.id = "timevarying.decode.paper_layout.voxel_centres";
  full.system = "timevarying";
  full.description = "a \"quoted\" description";
  full.status = conf::Status::Fail;
  full.message = "3 samples differ";
  full.stderrText = "line 1\nline 2\n";
  full.oracles = {{"exact", conf::Verdict::Fail, "3 differ", {{"mismatched_pixels", 3}, {"max_abs_diff_lsb", 1}}},
                  {"envelope", conf::Verdict::Pass, "inside", {{"outside", 0}, {"rmse", 0.125}}},
                  {"ideal", conf::Verdict::NotRun, "no GL", nlohmann::json::object()}};
  full.effects = {"texture.nearest", "output.unorm8"};
  full.findings = {{"softpipe.x", "a finding", {{"samples_changed", 2}}}};
  full.figures = {{"planes", 4}, {"steps", {0, 1}}};
  full.secondsGl = 0.25;
  full.secondsEmulation = 0.5;
  full.secondsReference = std::numeric_limits<double>::quiet_NaN();
  full.images.rendered = "images/a.png";
  full.images.errorMask = "images/a_mask.png";
  conf::PixelValues p;
  p.x = 3;
  p.y = 4;
  p.k = 5;
  p.oracle = "envelope";
  p.gl = 0.5;
  p.emulated = std::numeric_limits<double>::quiet_NaN();
  p.reference = 0.25;
  p.allowed = std::make_pair(0.125, 0.375);
  full.worstPixels = {p, p};
  conf::CaseResult pass;
  pass.id = "sparsegrid.hard.level1";
  pass.system = "sparsegrid";
  pass.description = "level 1";
  pass.oracles = {{"exact", conf::Verdict::Pass, "bit exact", {{"mismatched_pixels", 0}}}};
  conf::CaseResult crash = pass;
  crash.id = "runner.control.segfault";
  crash.status = conf::Status::Crash;
  crash.message = "killed by signal 11";
  crash.stderrText = "runner control: segfault\n";
  crash.oracles.clear();
  conf::CaseResult warn = pass;
  warn.status = conf::Status::Warn;
  warn.oracles.front().verdict = conf::Verdict::Warn;
  warn.oracles.front().figures = {{"mismatched_pixels", 7}};
  conf::RunInfo run;
  run.driver = {{"renderer", "llvmpipe (LLVM 15.0.6, 256 bits)"}, {"version", "4.5 (Core Profile) Mesa 22.3.6"}};
  run.command = "voxref conform --filter sparsegrid.hard.* --out out";
  run.started = "2024-01-01T00:00:00Z";
  run.finished = "2024-01-01T00:01:00Z";
  auto seed = [](const std::string& name, const conf::RunInfo& r, const std::vector<conf::CaseResult>& cases) {
    const std::string text = conf::resultsJson(r, cases).dump(2) + "\n";
    if (conf::parseResults(text, name).cases.size() != cases.size()) throw std::runtime_error(name + ": cases lost");
    write(name, text);
  };
  seed("four_cases.json", run, {full, pass, crash, warn});
  seed("one_case.json", run, {pass});
  seed("no_cases.json", run, {});
  conf::RunInfo interrupted = run;
  interrupted.complete = false;
  interrupted.interruptedBy = "SIGINT";
  interrupted.notRun = {"sparsegrid.hard.level2"};
  interrupted.baseline = {{"file", "old/results.json"}, {"regressed", false}};
  seed("interrupted.json", interrupted, {warn, full});
}

// --- CI files ----------------------------------------------------------------------------
void expectations() {
  const std::map<std::string, std::string> files{
      {"fails.txt",
       "# expected failures on softpipe\nsparsegrid.texture.r8.exact.linear.repeat,Fail\r\n"
       "iso.frames.buckyball,Crash\ntimevarying.hard.orbit,Timeout\nsparsegrid.hard.level12.rgba8,Warn\n"},
      {"flakes.txt", "# known flakes\n^timevarying\\.decode\\..*\\.orbit$\n[0-9]+\\.xray\n"},
      {"caselist.txt", "sparsegrid.hard.level1\n\n  iso.hard.single_voxel\n# end\n"},
      {"suite.toml",
       "[[conform]]\nname = \"llvmpipe\"\nfilter = \"sparsegrid.hard.*\"\nfails = [\"f.txt\"]\n"
       "fraction = 2\n[conform.env]\nGALLIUM_DRIVER = \"llvmpipe\"\n\n[[conform]]\nname = \"zink\"\n"
       "driver = \"egl\"\nrenderer_check = \"^zink\"\n"}};
  for (const auto& [name, text] : files) {
    conf::Expectations e;
    conf::parseFailsText(name == "fails.txt" ? text : "", name, e.fails);
    if (name == "flakes.txt" && conf::parsePatternsText(text, name).size() != 2)
      throw std::runtime_error(name + " does not read back");
    if (name == "caselist.txt" && conf::parseCaseListText(text, name).size() != 2)
      throw std::runtime_error(name + " does not read back");
    if (name == "suite.toml" && conf::parseSuiteText(text, name).size() != 2)
      throw std::runtime_error(name + " does not read back");
    write(name, text);
  }
}

// --- adaptive delta coder pages ----------------------------------------------------------------
void adaptivePage() {
  auto seed = [](const std::string& name, int bits, int components, const std::vector<std::int32_t>& deltas) {
    const std::string page = ref::encodeAdaptivePage(deltas, bits, components);
    ref::AdaptivePageReader reader(page, bits, components, 0, name);
    std::vector<std::int32_t> back(deltas.size());
    reader.read(back);
    reader.finish();
    if (back != deltas) throw std::runtime_error(name + " does not read back");
    const std::size_t n = deltas.size();
    std::string bytes{static_cast<char>((bits == 16 ? 1 : 0) | (components == 3 ? 2 : 0)), static_cast<char>(n & 0xff),
                      static_cast<char>(n >> 8)};
    write(name, bytes + page);
  };
  std::vector<std::int32_t> smooth, noisy, wide;
  std::uint32_t x = 54321;
  for (int i = 0; i < 300; ++i) {
    smooth.push_back(static_cast<std::int32_t>(std::lround(6 * std::sin(0.3 * i))));
    x = x * 1103515245u + 12345u;
    noisy.push_back(static_cast<std::int32_t>((x >> 16) % 256) - 128);
    wide.push_back(static_cast<std::int32_t>((x >> 8) % 65536) - 32768);
  }
  seed("smooth8.adaptive", 8, 1, smooth);
  seed("noisy8x3.adaptive", 8, 3, noisy);
  seed("wide16.adaptive", 16, 1, wide);
  seed("extremes8x3.adaptive", 8, 3, {0, -128, 127, 1, -1, 0, 0, -128, 64});
  seed("zeros8.adaptive", 8, 1, std::vector<std::int32_t>(4096, 0));
}

// --- context coder pages -----------------------------------------------------------------------
// Each seed is a header (context_page_input.h) and the page the encoder makes of the volume the
// target builds from it.
void contextPage() {
  auto seed = [](const std::string& name, std::string header) {
    const auto* h = reinterpret_cast<const std::uint8_t*>(header.data());
    const ref::HzOrder order(fuzz::contextPageGrid(h));
    const fuzz::ContextPageInput in = fuzz::contextPageInput(order, h);
    std::string page;
    if (in.gradients) {
      page = ref::encodeContextGradientPage(order, in.dims, in.pageBits, in.page, [&](const ref::GridPoint& q) {
        return in.vectors[ref::volumeIndex(q, in.dims)];
      });
      std::vector<std::array<std::int8_t, 3>> back = in.vectors;
      fuzz::decodeInputGradientPage(page, order, in, back);
      if (back != in.vectors) throw std::runtime_error(name + " does not read back");
    } else {
      const auto valueOf = [&](const ref::GridPoint& q) { return in.volume[ref::volumeIndex(q, in.dims)]; };
      page = ref::encodeContextPage(order, in.dims, in.bits, in.pageBits, in.page, valueOf);
      std::vector<std::int32_t> back = in.volume;
      fuzz::decodeInputPage(page, order, in, back);
      if (back != in.volume) throw std::runtime_error(name + " does not read back");
    }
    write(name, header + page);
  };
  // channel and bits, extents (minus one), page bits (minus four), page selector
  seed("cube8.context", std::string{0, 8, 8, 8, 0, 0});
  seed("cube8_last_page.context", std::string{0, 8, 8, 8, 0, 100});
  seed("thin16.context", std::string{1, 11, 0, 2, 2, 1});
  seed("slab8.context", std::string{0, 9, 5, 0, 1, 3});
  seed("single.context", std::string{0, 0, 0, 0, 0, 0});
  seed("cube8.gradients.context", std::string{2, 8, 8, 8, 0, 0});
  seed("slab8_last_page.gradients.context", std::string{2, 9, 5, 0, 1, 100});
  seed("single.gradients.context", std::string{2, 0, 0, 0, 0, 0});
}

}  // namespace

int main(int argc, char** argv) {
  const std::map<std::string, std::function<void()>> kinds{{"timevarying", timevarying},
                                                           {"huffman", huffman},
                                                           {"scene", scene},
                                                           {"raw_volume", rawVolume},
                                                           {"manifest", manifest},
                                                           {"results", results},
                                                           {"expectations", expectations},
                                                           {"adaptive_page", adaptivePage},
                                                           {"context_page", contextPage}};
  if (argc != 3 || !kinds.count(argv[1])) {
    std::cerr << "usage: make_fuzz_seeds "
                 "timevarying|huffman|adaptive_page|context_page|scene|raw_volume|manifest|results|expectations DIR\n";
    return 2;
  }
  outDir = argv[2];
  try {
    fs::create_directories(outDir);
    kinds.at(argv[1])();
  } catch (const std::exception& e) {
    std::cerr << "make_fuzz_seeds " << argv[1] << ": " << e.what() << "\n";
    return 1;
  }
  std::cout << "make_fuzz_seeds " << argv[1] << ": "
            << std::distance(fs::directory_iterator(outDir), fs::directory_iterator()) << " seeds in "
            << outDir.string() << "\n";
  return 0;
}
