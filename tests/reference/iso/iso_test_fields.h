// Test helper: small fields on LEB grids for the isosurface tests, built in closed form.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "reference/common/volume.h"
#include "reference/iso/grid_field.h"
#include "reference/leb/gradients.h"

namespace voxref::ref::test_support {

// A volume of dims with value f(x, y, z) (rounded to the nearest integer, clamped to uint16).
inline Volume<std::uint16_t> volumeOf(const Dims3& dims, const std::function<double(int, int, int)>& f) {
  Volume<std::uint16_t> v(dims);
  for (int z = 0; z < dims[2]; ++z)
    for (int y = 0; y < dims[1]; ++y)
      for (int x = 0; x < dims[0]; ++x)
        v.at(x, y, z) = static_cast<std::uint16_t>(std::lround(std::clamp(f(x, y, z), 0.0, 65535.0)));
  return v;
}

// A ball: 1000 - 100 * distance from c (values above 0 within radius 10).
inline Volume<std::uint16_t> ballVolume(const Dims3& dims, double cx, double cy, double cz) {
  return volumeOf(dims, [=](int x, int y, int z) {
    return 1000.0 - 100.0 * std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz));
  });
}

inline DenseGridField denseField(const Volume<std::uint16_t>& v) { return DenseGridField(v, quantizedGradients(v)); }

}  // namespace voxref::ref::test_support
