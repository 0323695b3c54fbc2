// Transfer functions: scalar (uint8) -> RGBA8 colour, the mapping Binotto et al. 2003 apply before
// storing homogeneous cells and refinement blocks (section 5.1.1).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "reference/common/rgba.h"

namespace voxref::ref {

struct TransferFunction {
  std::string name;
  std::array<Rgba8, 256> table{};
  const Rgba8& operator()(std::uint8_t v) const { return table[v]; }
};

// Built-in transfer functions:
//   plume      0 -> transparent black; 1..255 -> a blue-to-yellow ramp, alpha rising from 8 to 240
//              (never 255: no homogeneous colour can be mistaken for a refinement flag)
//   opaque     like plume, but values >= 200 are opaque (alpha 255): the flag collision of the
//              paper's alpha = 1 convention (section 5.2)
//   gray       v -> (v, v, v, v)
// Throws std::invalid_argument listing the names for an unknown one.
TransferFunction transferFunction(std::string_view name);
std::vector<std::string> transferFunctionNames();

}  // namespace voxref::ref
