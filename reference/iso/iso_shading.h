// The one shading rule of isosurface images, shared by the GL renderer, the Embree ground truth
// and their comparison: two-sided Lambert with a headlight (the light at the eye), as the paper's
// figures are lit (Gregorski et al. 2004, section 5: "shaded with the gradients").
//   shade = kAmbient + (1 - kAmbient) * |n . l|,  l = unit vector from the surface point to the eye.
// Two-sided, so the orientation of a triangle (or the sign of a gradient) cannot change an image.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace voxref::ref {

inline constexpr double kIsoAmbient = 0.15;

// n: unit normal; toEye: unit vector towards the eye. In [kIsoAmbient, 1].
inline double isoShade(const glm::dvec3& n, const glm::dvec3& toEye) {
  return kIsoAmbient + (1.0 - kIsoAmbient) * std::fabs(glm::dot(n, toEye));
}

}  // namespace voxref::ref
