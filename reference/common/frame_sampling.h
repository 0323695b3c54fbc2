// Evaluating a field at every sample of a plane frame: the reference backend's planes.
#pragma once

#include <functional>

#include <glm/vec3.hpp>

#include "reference/common/plane_frame.h"
#include "reference/common/plane_shading.h"

namespace voxref::ref {

// True when p lies in the closed unit cube. Samples outside it are background (value 0): the GL
// path discards those fragments, so nothing is blended there.
bool insideUnitCube(glm::dvec3 p);

// fn(p) at every sample of `frame` inside the unit cube, 0 outside. Planes are split among
// `threads` workers (0 = hardware concurrency); every value is computed by the same code
// whatever the split, so the result is identical for every thread count. `fn` must be safe to
// call concurrently. `progress` (optional) is called with the number of planes done so far.
SampleStack sampleFrame(const PlaneFrame& frame, const std::function<double(glm::dvec3)>& fn, int threads = 0,
                        const std::function<void(int)>& progress = {});

}  // namespace voxref::ref
