#include "reference/timevarying/exact_colours.h"

#include <algorithm>
#include <cmath>

namespace voxref::ref {
namespace {

bool insideUnitCube(const glm::dvec3& p) {
  return p.x >= 0 && p.y >= 0 && p.z >= 0 && p.x <= 1 && p.y <= 1 && p.z <= 1;
}

}  // namespace

Rgba8 inputColour(const TimeSeries& input, const TransferFunction& tf, int step, const glm::dvec3& p) {
  std::size_t at = 0;
  for (int a = 2; a >= 0; --a)
    at = at * static_cast<std::size_t>(input.side) +
         static_cast<std::size_t>(std::min(static_cast<int>(std::floor(p[a] * input.side)), input.side - 1));
  return tf(input.steps[static_cast<std::size_t>(step)][at]);
}

RgbaStack exactColours(const TimeSeries& input, const TransferFunction& tf, int step, const PlaneFrame& f) {
  RgbaStack out{f.width, f.height, f.planes, {}};
  out.colours.reserve(static_cast<std::size_t>(f.width) * f.height * f.planes);
  for (int k = 0; k < f.planes; ++k)
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        const glm::dvec3 p = f.sample(i, j, k);
        out.colours.push_back(insideUnitCube(p) ? inputColour(input, tf, step, p) : Rgba8{0, 0, 0, 0});
      }
  return out;
}

std::vector<std::array<double, 4>> idealComposite(const RgbaStack& exact, const PlaneFrame& f) {
  std::vector<std::array<double, 4>> out(static_cast<std::size_t>(f.width) * f.height, {0, 0, 0, 0});
  for (int k = f.planes - 1; k >= 0; --k)
    for (int j = 0; j < f.height; ++j)
      for (int i = 0; i < f.width; ++i) {
        if (!insideUnitCube(f.sample(i, j, k))) continue;
        const Rgba8& s = exact.at(i, j, k);
        auto& d = out[static_cast<std::size_t>(i) + static_cast<std::size_t>(f.width) * j];
        const double a = s[3] / 255.0;
        for (int c = 0; c < 4; ++c) d[c] = s[c] * a + d[c] * (1.0 - a);
      }
  return out;
}

}  // namespace voxref::ref
