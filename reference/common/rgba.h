// RGBA8 colours and stacks of them: what the time-varying decoders output per sample.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace voxref::ref {

using Rgba8 = std::array<std::uint8_t, 4>;

// Colours of every sample of a plane frame (plane_frame.h): (i, j, k) at i + width (j + height k),
// row j = 0 at the bottom. A single image is a stack of one plane.
struct RgbaStack {
  int width = 0, height = 0, planes = 0;
  std::vector<Rgba8> colours;
  const Rgba8& at(int i, int j, int k) const {
    return colours[static_cast<std::size_t>(i) +
                   static_cast<std::size_t>(width) * (j + static_cast<std::size_t>(height) * k)];
  }
};

}  // namespace voxref::ref
