#include "conformance/modules/sparsegrid/prepared_scene.h"
#include "conformance/framework/stopwatch.h"

#include <algorithm>
#include <chrono>

#include "reference/common/frame_sampling.h"

namespace voxref::conf {
namespace {

void applyPassOrder(ref::CombinationTextures& textures, const std::vector<int>& order) {
  if (order.empty()) return;
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i)
    if (sorted.size() != textures.passes.size() || sorted[i] != static_cast<int>(i))
      throw SceneError("pass_order: expected a permutation of 0.." + std::to_string(textures.passes.size() - 1));
  std::vector<ref::CombinationPass> passes;
  for (int p : order) passes.push_back(textures.passes[static_cast<std::size_t>(p)]);
  textures.passes = std::move(passes);
}

}  // namespace

PreparedScene prepareScene(const SparseGridScene& scene) {
  PreparedScene p;
  p.scene = scene;
  p.frame = makeFrame(scene);
  const auto t0 = Clock::now();
  const ref::SparseGrid grid = ref::SparseGrid::fromField(scene.grid, loadField(scene.data));
  p.combination = std::make_shared<const ref::Combination>(grid);
  p.secondsBuild = secondsSince(t0);
  p.textures = ref::buildCombinationTextures(*p.combination, scene.textures);
  applyPassOrder(p.textures, scene.passOrder);
  return p;
}

ref::SampleStack referencePlanes(const PreparedScene& prepared, int threads, const std::function<void(int)>& progress) {
  const ref::Combination& c = *prepared.combination;
  return ref::sampleFrame(
      prepared.frame, [&c](glm::dvec3 p) { return c.value(p); }, threads, progress);
}

}  // namespace voxref::conf
