#include "conformance/modules/iso/iso_session.h"
#include "conformance/framework/stopwatch.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "fixtures/raycast/mesh_raycast.h"
#include "reference/iso/diamond_bounds.h"
#include "reference/iso/extraction.h"
#include "reference/iso/grid_field.h"
#include "reference/iso/incremental_extraction.h"
#include "reference/iso/isovalue_mask.h"
#include "reference/leb/gradients.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_stream.h"

namespace voxref::conf {
namespace {

gpu::QueryBox queryBox(const ref::LebGrid& g, const ref::GridPoint& d, const ref::Dims3& dims) {
  const ref::GridBox b = ref::diamondBox(g, d);
  gpu::QueryBox q;
  for (int a = 0; a < 3; ++a) {
    q.lo[static_cast<std::size_t>(a)] =
        std::min<double>(b.lo[a], dims[static_cast<std::size_t>(a)] - 1) - kQueryBoxMargin;
    q.hi[static_cast<std::size_t>(a)] =
        std::min<double>(b.hi[a], dims[static_cast<std::size_t>(a)] - 1) + kQueryBoxMargin;
  }
  return q;
}

}  // namespace

std::vector<IsoFrame> runIsoFrames(gpu::Context& gl, const IsoScene& scene, const IsoRunOptions& options) {
  const ref::Volume<std::uint16_t> volume = isoSceneVolume(scene);
  ref::DenseGridField dense(volume, ref::quantizedGradients(volume));
  const ref::DiamondBounds bounds = ref::computeDiamondBounds(dense.grid(), dense.values(), options.threads);
  // The stream's sample width: 8 bits when every voxel fits (the built-in scenes, uint8 volumes),
  // else 16 (a user's uint16 volume); lossless either way (reference/leb/FORMAT.md).
  const bool fits8 = std::all_of(volume.data().begin(), volume.data().end(), [](std::uint16_t v) { return v <= 255; });
  auto stream = std::make_shared<const ref::LebStream>(ref::parseLebStream(ref::encodeLeb(volume, fits8 ? 8 : 16)));
  ref::CompressedGridField field(stream, std::size_t{64} << 20);
  return runIsoFrames(gl, scene, field, bounds, options);
}

std::vector<IsoFrame> runIsoFrames(gpu::Context& gl, const IsoScene& scene, ref::CompressedGridField& field,
                                   const ref::DiamondRanges& given, const IsoRunOptions& options) {
  const ref::LebGrid grid = field.grid();
  if (given.lebGrid().k != grid.k)
    throw std::invalid_argument("isosurface frames: the bounds' grid is not the stream's");
  const ref::Dims3 dims = field.volumeDims();
  const ref::HzOrder order(grid);

  double iso = scene.isovalue;
  // A full table is asked through its bits for the frame's isovalue (isovalue_mask.h): the same
  // answers with fewer waits on memory. Other bounds (the tiered table) are asked as they are.
  std::optional<ref::IsovalueMask> mask;
  if (const auto* table = dynamic_cast<const ref::DiamondBounds*>(&given)) mask.emplace(*table, iso);
  const ref::DiamondRanges& bounds = mask ? static_cast<const ref::DiamondRanges&>(*mask) : given;
  ref::ViewRefinement refinement(bounds, iso);
  // Each frame reads only the leaf tetrahedra that were not leaves the frame before; the same mesh,
  // bit for bit, as extractIsosurface (incremental_extraction.h).
  ref::IncrementalExtraction extraction(grid, dims, &bounds, iso);
  std::unordered_map<std::uint64_t, int> visibleAt;  // diamond (linear index) -> frame it was found visible
  // Holds the mesh it drew last: the next frame's occluder (section 5: the previous frame's surface).
  gpu::IsoMeshRenderer renderer(gl);
  bool occludersValid = false;
  std::vector<IsoFrame> frames;
  for (int f = 0; f < scene.path.frames; ++f) {
    IsoFrame fr;
    fr.frame = f;
    if (f == scene.isovalueChangeFrame) {
      iso += scene.isovalueStep;
      if (mask) mask->setIsovalue(iso);
      refinement.setIsovalue(iso);
      extraction.setIsovalue(iso);
      visibleAt.clear();
      occludersValid = false;  // the previous surface is not this isovalue's
    }
    fr.isovalue = iso;
    fr.camera = ref::orbitCamera(scene.path, f, scene.camera);

    std::unordered_set<std::uint64_t> culled;  // diamonds (linear index) culled this frame
    auto isCulled = [&](const ref::GridPoint& d) { return culled.count(grid.linearIndex(d)) != 0; };
    double secondsComparing = 0;  // the other counter's, left out of the frame's timings
    auto queryDiamonds = [&](const std::vector<ref::GridPoint>& diamonds) {  // against the renderer's mesh
      std::vector<gpu::QueryBox> boxes;
      for (const ref::GridPoint& d : diamonds) boxes.push_back(queryBox(grid, d, dims));
      std::vector<std::uint32_t> samples = renderer.occlusionQueries(boxes, fr.camera, options.counter);
      if (options.compareCounters) {
        const auto t = Clock::now();
        const bool byQueries = options.counter == gpu::SampleCounter::Queries;
        const std::vector<std::uint32_t> other = renderer.occlusionQueries(
            boxes, fr.camera, byQueries ? gpu::SampleCounter::Buffer : gpu::SampleCounter::Queries);
        SampleCountComparison c = byQueries ? compareSampleCounts(samples, other) : compareSampleCounts(other, samples);
        if (!c.first.empty()) c.first = "frame " + std::to_string(f) + ", " + c.first;
        accumulate(fr.counters, c);
        secondsComparing += secondsSince(t);
      }
      return samples;
    };
    auto refineAndExtract = [&] {
      auto t = Clock::now();
      const ref::RefinementStats st = refinement.update(fr.camera, scene.budget, isCulled);
      fr.refinement.splits += st.splits;
      fr.refinement.merges += st.merges;
      fr.refinement.splitQueue = st.splitQueue;
      fr.refinement.mergeQueue = st.mergeQueue;
      fr.refinement.budgetExhausted = fr.refinement.budgetExhausted || st.budgetExhausted;
      fr.secondsRefine += secondsSince(t);
      t = Clock::now();
      ref::ExtractionStats es;
      fr.mesh = extraction.update(refinement.mesh(), field, &es);
      fr.secondsExtract += secondsSince(t);
      fr.triangles = es.triangles;
      fr.leafTetrahedra = es.leafTetrahedra;
    };

    // 1. Occlusion queries against the previous frame's surface.
    std::vector<ref::GridPoint> tested;
    auto t0 = Clock::now();
    if (scene.occlusionCulling && occludersValid) {
      for (const auto& queue : {refinement.splitQueue(), refinement.mergeQueue()})
        for (const ref::GridPoint& d : queue) {
          if (!bounds.mayContain(d, iso)) continue;
          const auto it = visibleAt.find(grid.linearIndex(d));
          if (it != visibleAt.end() && f - it->second < scene.retestVisibleEvery) continue;
          tested.push_back(d);
        }
      const std::vector<std::uint32_t> samples = queryDiamonds(tested);  // the last frame's mesh, still loaded
      for (std::size_t i = 0; i < tested.size(); ++i) {
        const std::uint64_t id = grid.linearIndex(tested[i]);
        if (samples[i] == 0 || scene.cullEveryTested) {
          culled.insert(id);
        } else {
          visibleAt[id] = f;
        }
      }
    }
    fr.occlusionTests = tested.size();
    fr.secondsQueries = secondsSince(t0) - secondsComparing;
    secondsComparing = 0;

    // 2. Refinement; 3. extraction.
    refineAndExtract();

    // Optional verification: culled diamonds whose boxes show against this frame's own surface
    // are un-culled and the frame is refined and extracted again.
    if (scene.verifyCulls && !culled.empty()) {
      t0 = Clock::now();
      std::vector<ref::GridPoint> suspects;
      for (const ref::GridPoint& d : tested)
        if (isCulled(d)) suspects.push_back(d);
      renderer.load(fr.mesh);
      const std::vector<std::uint32_t> samples = queryDiamonds(suspects);
      for (std::size_t i = 0; i < suspects.size(); ++i)
        if (samples[i] != 0) {
          culled.erase(grid.linearIndex(suspects[i]));
          visibleAt[grid.linearIndex(suspects[i])] = f;
          ++fr.revokedCulls;
        }
      fr.secondsQueries += secondsSince(t0) - secondsComparing;
      if (fr.revokedCulls > 0) refineAndExtract();
    }
    fr.culled = culled.size();
    fr.pagesDecoded = field.reader().cacheStats().misses;

    // 4. The frame's image as a display shows it (timed); then the oracles' image of the same mesh,
    // with its primitive ids and depth, and Embree's ground truth (neither timed: they are the
    // oracles' work, not the frame's; docs/iso.md).
    t0 = Clock::now();
    renderer.load(fr.mesh);
    (void)renderer.display(fr.camera);
    fr.secondsGl = secondsSince(t0);
    fr.gl = renderer.render(fr.camera);
    t0 = Clock::now();
    fr.truth = fx::castMesh(fr.mesh, fr.camera, options.threads);
    fr.secondsEmbree = secondsSince(t0);
    std::unordered_set<ref::DiamondId> visible(fr.truth.item.begin(), fr.truth.item.end());
    visible.erase(ref::kNoDiamond);
    fr.visibleDiamonds = visible.size();
    for (const auto& queue : {refinement.splitQueue(), refinement.mergeQueue()})
      for (const ref::GridPoint& d : queue) {
        if (!bounds.mayContain(d, iso)) continue;
        const bool seen = visible.count(static_cast<ref::DiamondId>(order.index(d))) != 0;
        if (!seen) ++fr.invisibleCandidates;
      }
    // A culled diamond is judged where it ended: still a leaf (its own tetrahedra), or merged
    // (its tetrahedra then belong to it as a leaf again); either way by its own id.
    for (std::uint64_t id : culled) {
      if (visible.count(static_cast<ref::DiamondId>(order.index(grid.pointAt(id)))) != 0) {
        ++fr.falseCulls;
      } else {
        ++fr.culledInvisible;
      }
    }
    occludersValid = true;
    if (!options.keepImages && !frames.empty()) {
      frames.back().mesh = {};
      frames.back().gl = {};
      frames.back().truth = {};
    }
    frames.push_back(std::move(fr));
    if (options.progress) options.progress(f);
  }
  return frames;
}

}  // namespace voxref::conf
