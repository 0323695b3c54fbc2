// A sparse-grid scene made ready to render: the sparse grid sampled and hierarchized, its
// combination grids, the textures and passes of the hardware method, and the plane frame. One
// function builds it for the conformance cases and for `voxref render`.
#pragma once

#include <functional>
#include <memory>

#include "conformance/modules/sparsegrid/sparsegrid_scene.h"
#include "reference/common/plane_frame.h"
#include "reference/common/plane_shading.h"
#include "reference/sparsegrid/combination.h"
#include "reference/sparsegrid/combination_textures.h"

namespace voxref::conf {

struct PreparedScene {
  SparseGridScene scene;
  ref::PlaneFrame frame;
  std::shared_ptr<const ref::Combination> combination;
  ref::CombinationTextures textures;  // passes in scene.passOrder when given
  double secondsBuild = 0.0;          // sampling, hierarchization, combination grids
};

// Throws SceneError (bad frame, bad pass order) or io::IoError (volume file).
PreparedScene prepareScene(const SparseGridScene& scene);

// The double reference at every sample: the combination technique (eq. 11) in double, 0 outside
// the unit cube. `progress` gets the number of planes done.
ref::SampleStack referencePlanes(const PreparedScene& prepared, int threads,
                                 const std::function<void(int)>& progress = {});

}  // namespace voxref::conf
