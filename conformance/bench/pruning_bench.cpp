#include "conformance/bench/pruning_bench.h"
#include "conformance/framework/selection.h"

#include <cstring>
#include <set>
#include <tuple>

#include "conformance/modules/catalog.h"
#include "conformance/modules/sparsegrid/prepared_scene.h"
#include "conformance/modules/sparsegrid/sparsegrid_scene.h"
#include "conformance/modules/timevarying/timevarying_scene.h"
#include "emulation/combination_emu.h"
#include "emulation/timevarying_emu.h"
#include "reference/common/parallel.h"
#include "reference/timevarying/transfer_function.h"

namespace voxref::conf {
namespace {

std::string joined(const std::vector<emu::Effect>& effects) {
  std::string s;
  for (std::string_view id : emu::effectIds(effects)) s += (s.empty() ? "" : ", ") + std::string(id);
  return s;
}

void addRow(BenchTable& t, const std::string& id, const std::string& state, const std::string& pruned, const Timing& p,
            const Timing& f, bool identical) {
  const double ratio = p.median > 0 ? f.median / p.median : 0.0;
  t.rows.push_back({id, state, pruned, formatSeconds(p), formatSeconds(f), formatNumber("%.2f", ratio),
                    identical ? "yes" : "**NO**"});
  t.data["rows"].push_back({{"case", id},
                            {"state", state},
                            {"pruned_stages", pruned},
                            {"pruned", toJson(p)},
                            {"forced", toJson(f)},
                            {"forced_over_pruned", ratio},
                            {"identical", identical}});
}

// The header both tables share: `what` names the system.
BenchTable pruningTable(const std::string& id, const std::string& what, const emu::PrecisionProfile& profile) {
  BenchTable t;
  t.id = id;
  t.title = "Effect pruning, " + what +
            ": emulation with only the scene's effects vs every effect forced on (profile " +
            std::string(profile.name) + ")";
  t.columns = {"case (built-in scene)", "state",         "stages pruned", "pruned", "forced",
               "forced / pruned",       "identical bits"};
  return t;
}

// One case per distinct sampling / framebuffer state (the first in catalogue order), at most `cap`.
BenchTable combinationTable(const BenchOptions& o, const emu::PrecisionProfile& profile) {
  BenchTable t = pruningTable("pruning.combination", "combination technique", profile);
  std::set<std::tuple<int, int, int, int, bool>> seen;
  const std::size_t cap = o.quick ? 4 : 10;
  // Scenes where pruning removes the most first: NEAREST sampling, then float framebuffers, then the rest.
  std::vector<std::pair<std::string, SparseGridScene>> ordered[3];
  for (const Case& c : allCases()) {
    if (!c.scene || c.scene->value("system", "sparsegrid") != "sparsegrid") continue;
    try {
      SparseGridScene scene = parseSparseGridScene(*c.scene);
      if (scene.data.isVolume()) continue;
      const int rank = scene.sampler.filter == ref::Filter::Nearest ? 0
                       : ref::unormBits(scene.framebuffer) == 0     ? 1
                                                                    : 2;
      ordered[rank].emplace_back(c.id, std::move(scene));
    } catch (const std::exception&) {
    }
  }
  std::vector<std::pair<std::string, SparseGridScene>> candidates;
  std::vector<int> rankOf;
  for (int r = 0; r < 3; ++r)
    for (auto& x : ordered[r]) {
      candidates.push_back(std::move(x));
      rankOf.push_back(r);
    }
  const std::size_t perRank[3] = {o.quick ? 2u : 4u, o.quick ? 1u : 3u, o.quick ? 1u : 3u};
  std::size_t taken[3] = {0, 0, 0};
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const auto& caseId = candidates[k].first;
    const auto& scene = candidates[k].second;  // not a structured binding: clang 14 cannot capture one
    if (seen.size() >= cap) break;
    if (taken[rankOf[k]] >= perRank[rankOf[k]]) continue;
    const struct { std::string id; } c{caseId};
    if (!seen.insert({static_cast<int>(scene.textures.format), static_cast<int>(scene.sampler.filter),
                      static_cast<int>(scene.sampler.wrap), static_cast<int>(scene.framebuffer), scene.flushEachPass})
             .second)
      continue;
    const PreparedScene prepared = prepareScene(scene);
    emu::CombinationEmuOptions pruned{scene.flushEachPass, o.threads, false},
        forced{scene.flushEachPass, o.threads, true};
    emu::EmulatedPlanes a, b;
    try {
      const Timing tp = measure([&] {
        a = emu::emulateCombination(prepared.textures, prepared.frame, scene.sampler, scene.framebuffer, profile,
                                    pruned);
      });
      const Timing tf = measure([&] {
        b = emu::emulateCombination(prepared.textures, prepared.frame, scene.sampler, scene.framebuffer, profile,
                                    forced);
      });
      std::string skipped;
      if (scene.sampler.filter == ref::Filter::Nearest) skipped = "weights + lerps (nearest)";
      if (ref::unormBits(scene.framebuffer) == 0)
        skipped += std::string(skipped.empty() ? "" : "; ") + "clamp" +
                   (scene.framebuffer == ref::FramebufferFormat::RGBA32F ? " + tile store" : "");
      if (skipped.empty()) skipped = "none";
      const std::string state = std::string(ref::name(scene.textures.format)) + " " +
                                std::string(ref::name(scene.sampler.filter)) + " " +
                                std::string(ref::name(scene.sampler.wrap)) + " -> " +
                                std::string(ref::name(scene.framebuffer)) + (scene.flushEachPass ? " flush" : "");
      addRow(t, c.id, state, skipped, tp, tf, a.planes.codes == b.planes.codes && a.unmodelled == b.unmodelled);
      ++taken[rankOf[k]];
      t.data["rows"].back()["effects"] =
          joined(emu::combinationEffects(prepared.textures, scene.sampler, scene.framebuffer, profile, pruned,
                                         prepared.frame.width, prepared.frame.height));
    } catch (const std::invalid_argument&) {  // the profile cannot model the target size
      seen.erase({static_cast<int>(scene.textures.format), static_cast<int>(scene.sampler.filter),
                  static_cast<int>(scene.sampler.wrap), static_cast<int>(scene.framebuffer), scene.flushEachPass});
    }
  }
  return t;
}

BenchTable timeVaryingTable(const BenchOptions& o, const emu::PrecisionProfile& profile) {
  BenchTable t = pruningTable("pruning.timevarying", "time-varying decoders", profile);
  std::set<std::tuple<int, int, bool>> seen;
  const std::size_t cap = o.quick ? 3 : 6;
  for (const Case& c : allCases()) {
    if (seen.size() >= cap) break;
    if (!c.scene || c.scene->value("system", "sparsegrid") != "timevarying") continue;
    TimeVaryingScene scene;
    try {
      scene = parseTimeVaryingScene(*c.scene);
    } catch (const std::exception&) {
      continue;
    }
    if (!seen.insert({static_cast<int>(scene.decoder), static_cast<int>(scene.encoding.encoding), scene.composite})
             .second)
      continue;
    const ref::TimeSeries series = makeSeries(scene);
    const ref::TimeVaryingTextures tex =
        ref::encodeTimeVarying(series, ref::transferFunction(scene.transfer), scene.encoding);
    const ref::PlaneFrame frame = makeFrame(scene, tex.layout);
    const int step = stepsOf(scene).front();
    bool identical = true;
    Timing tp, tf;
    if (scene.composite) {
      ref::RgbaStack a, b;
      tp = measure(
          [&] { a = emu::emulateComposite(tex, scene.decoder, step, frame, profile, o.threads, false, false); });
      tf =
          measure([&] { b = emu::emulateComposite(tex, scene.decoder, step, frame, profile, o.threads, false, true); });
      identical = a.colours == b.colours;
    } else {
      emu::EmulatedDecode a, b;
      tp = measure([&] { a = emu::emulateDecodePlanes(tex, scene.decoder, step, frame, profile, o.threads, false); });
      tf = measure([&] { b = emu::emulateDecodePlanes(tex, scene.decoder, step, frame, profile, o.threads, true); });
      identical = a.colours.colours == b.colours.colours && a.samples.size() == b.samples.size();
      for (std::size_t i = 0; identical && i < a.samples.size(); ++i)
        identical = std::memcmp(a.samples[i].value.data(), b.samples[i].value.data(), sizeof(float) * 4) == 0;
    }
    const std::string state = std::string(ref::name(scene.decoder)) + " / " +
                              std::string(ref::name(scene.encoding.encoding)) +
                              (scene.composite ? ", composited" : ", planes");
    addRow(
        t, c.id, state,
        scene.decoder == ref::DecoderVariant::TexelFetch ? "weights + lerps (texelFetch)" : "weights + lerps (nearest)",
        tp, tf, identical);
  }
  return t;
}

const char* kNotes =
    "Pruned: the stages the scene's state calls for (the case's `effects`). Forced (`forceAllEffects` in the emulator "
    "options): every stage the "
    "pruning skips is run anyway, as an identity: NEAREST fetches (and texelFetch) run the LINEAR path's float weights "
    "and the seven trilinear "
    "lerps per channel with every tap on the fetched texel; float framebuffers run the per-pass clamp of source and "
    "result with the format's "
    "bounds (-inf, +inf) and a float32 tile is stored and reloaded every pass. Times are medians of up to five runs in "
    "this process, on ";

}  // namespace

std::vector<std::string> pruningBenchIds() { return {"pruning.combination", "pruning.timevarying"}; }

std::vector<BenchTable> pruningBench(const BenchOptions& o, const emu::PrecisionProfile* chosen) {
  std::vector<BenchTable> tables;
  const emu::PrecisionProfile* profile = chosen ? chosen : emu::findProfile("llvmpipe");
  const std::string notes =
      kNotes + std::to_string(ref::workerCount(o.threads)) +
      " thread(s). 'identical bits': every code (and for decoded planes every sample's float32 value) compared.";
  if (globMatch(o.filter, "pruning.combination")) {
    tables.push_back(combinationTable(o, *profile));
    tables.back().notes = notes;
  }
  if (globMatch(o.filter, "pruning.timevarying")) {
    tables.push_back(timeVaryingTable(o, *profile));
    tables.back().notes = notes;
  }
  return tables;
}

}  // namespace voxref::conf
