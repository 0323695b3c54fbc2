// The gradients the LEB codec stores beside the data (Gregorski et al. 2004, sections 2 and 3.1:
// "the normalized gradient vector at each data point ... quantized in three bytes with one byte
// per component").
//
// g = central differences of the samples (x fastest), one-sided on the volume's faces (and 0
// along an axis of extent 1), divided by the sample spacing. Each component of g / |g| is stored
// as snorm8, round(127 c) (GL 4.6 section 2.3.5.1, the inverse of snorm8 to float); a zero
// gradient is stored as (0, 0, 0). Computed in double; the rounding is std::lround (half away
// from zero). The paper smooths the float gradients by diffusion first; voxref does not.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/common/volume.h"

namespace voxref::ref {

// Three int8 per sample, (gx, gy, gz), in the order of the volume's samples.
std::vector<std::int8_t> quantizedGradients(const Volume<std::uint16_t>& volume);

}  // namespace voxref::ref
