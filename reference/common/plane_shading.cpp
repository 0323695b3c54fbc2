#include "reference/common/plane_shading.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace voxref::ref {

std::string_view name(RenderMode m) {
  switch (m) {
    case RenderMode::XRay:
      return "xray";
    case RenderMode::Mip:
      return "mip";
    case RenderMode::Iso:
      return "iso";
  }
  return "?";
}

std::optional<RenderMode> parseRenderMode(std::string_view s) {
  if (s == "xray") return RenderMode::XRay;
  if (s == "mip") return RenderMode::Mip;
  if (s == "iso") return RenderMode::Iso;
  return std::nullopt;
}

namespace {

// Derivative along one lattice axis by central differences, one-sided at the border.
double latticeDerivative(const SampleStack& s, int i, int j, int k, int axis) {
  const int n = axis == 0 ? s.width : axis == 1 ? s.height : s.planes;
  const int c = axis == 0 ? i : axis == 1 ? j : k;
  if (n < 2) return 0.0;
  auto at = [&](int offset) {
    return axis == 0 ? s.at(i + offset, j, k) : axis == 1 ? s.at(i, j + offset, k) : s.at(i, j, k + offset);
  };
  if (c == 0) return at(1) - at(0);
  if (c == n - 1) return at(0) - at(-1);
  return 0.5 * (at(1) - at(-1));
}

// World-space gradient from lattice derivatives: moving one step along an axis moves by that
// axis' step vector, so grad = sum_a (df/da) * d_a / |d_a|^2 for orthogonal steps.
glm::dvec3 worldGradient(const SampleStack& s, const PlaneFrame& f, int i, int j, int k) {
  const glm::dvec3 steps[3] = {f.dx, f.dy, f.dz};
  glm::dvec3 g{0.0};
  for (int a = 0; a < 3; ++a) {
    const double len2 = glm::dot(steps[a], steps[a]);
    if (len2 > 0.0) g += latticeDerivative(s, i, j, k, a) * steps[a] / len2;
  }
  return g;
}

double shadeIso(const SampleStack& s, const PlaneFrame& f, const ShadingParams& p, int i, int j) {
  for (int k = 1; k < s.planes; ++k) {
    const double a = s.at(i, j, k - 1), b = s.at(i, j, k);
    if ((a >= p.isovalue) == (b >= p.isovalue)) continue;
    const double t = (p.isovalue - a) / (b - a);
    const glm::dvec3 g = (1.0 - t) * worldGradient(s, f, i, j, k - 1) + t * worldGradient(s, f, i, j, k);
    const double len = glm::length(g);
    const glm::dvec3 view = glm::normalize(f.dz);
    const double lambert = len > 0.0 ? std::fabs(glm::dot(g, view)) / len : 1.0;
    return p.ambient + (1.0 - p.ambient) * lambert;
  }
  return 0.0;
}

}  // namespace

Image shadePlanes(const SampleStack& s, const PlaneFrame& f, const ShadingParams& p) {
  if (s.width != f.width || s.height != f.height || s.planes != f.planes ||
      s.values.size() != static_cast<std::size_t>(f.width) * f.height * f.planes)
    throw std::invalid_argument("sample stack does not match the frame's size");
  Image img{f.width, f.height, std::vector<double>(static_cast<std::size_t>(f.width) * f.height, 0.0)};
  const double stepLength = glm::length(f.dz);
  for (int j = 0; j < f.height; ++j)
    for (int i = 0; i < f.width; ++i) {
      double v = 0.0;
      switch (p.mode) {
        case RenderMode::XRay:
          for (int k = 0; k < f.planes; ++k) v += s.at(i, j, k);
          v *= stepLength;
          break;
        case RenderMode::Mip:
          for (int k = 0; k < f.planes; ++k) v = std::max(v, s.at(i, j, k));
          break;
        case RenderMode::Iso:
          v = shadeIso(s, f, p, i, j);
          break;
      }
      img.pixels[static_cast<std::size_t>(i) + static_cast<std::size_t>(f.width) * j] = v;
    }
  return img;
}

}  // namespace voxref::ref
