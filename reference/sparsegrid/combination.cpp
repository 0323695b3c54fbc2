#include "reference/sparsegrid/combination.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/common/rounding.h"

namespace voxref::ref {

std::vector<ComponentGridShape> combinationGridShapes(int n) {
  if (n < kMinSparseLevel || n > kMaxSparseLevel)
    throw std::invalid_argument("sparse grid level " + std::to_string(n) + " is outside " +
                                std::to_string(kMinSparseLevel) + ".." + std::to_string(kMaxSparseLevel));
  std::vector<ComponentGridShape> shapes;
  // Paper order: |l| = n + 2 (+1), |l| = n (+1), |l| = n + 1 (-2); (l1, l2) lexicographic.
  const std::array<std::pair<int, int>, 3> groups{{{n + 2, 1}, {n, 1}, {n + 1, -2}}};
  for (const auto& [sum, coefficient] : groups)
    for (int l1 = 1; l1 <= n; ++l1)
      for (int l2 = 1; l2 <= n; ++l2) {
        const int l3 = sum - l1 - l2;
        if (l3 >= 1) shapes.push_back({{l1, l2, l3}, coefficient});
      }
  return shapes;
}

Combination::Combination(const SparseGrid& grid) : level_(grid.spec().level), boundary_(grid.spec().boundary) {
  const int n = level_;
  for (const ComponentGridShape& shape : combinationGridShapes(n)) {
    const Levels3& l = shape.levels;
    ComponentGrid g{l, shape.coefficient, Volume<double>({(1 << l[0]) + 1, (1 << l[1]) + 1, (1 << l[2]) + 1})};
    for (int c = 0; c <= (1 << l[2]); ++c)
      for (int b = 0; b <= (1 << l[1]); ++b)
        for (int a = 0; a <= (1 << l[0]); ++a)
          g.values.at(a, b, c) =
              grid.nodalAt({static_cast<std::int64_t>(a) << (n - l[0]), static_cast<std::int64_t>(b) << (n - l[1]),
                            static_cast<std::int64_t>(c) << (n - l[2])});
    if (shape.coefficient > 0) ++positiveCount_;
    grids_.push_back(std::move(g));
  }
}

namespace {

struct Cell {
  int i0[3];
  double w[3];
};

Cell cellOf(const Levels3& levels, glm::dvec3 p) {
  const double c[3] = {std::clamp(p.x, 0.0, 1.0), std::clamp(p.y, 0.0, 1.0), std::clamp(p.z, 0.0, 1.0)};
  Cell cell;
  for (int a = 0; a < 3; ++a) {
    const double t = scaleByPowerOfTwo(c[a], levels[a]);  // exact
    cell.i0[a] = std::min(static_cast<int>(std::floor(t)), (1 << levels[a]) - 1);
    cell.w[a] = t - cell.i0[a];
  }
  return cell;
}

double lerp(double a, double b, double t) { return (1.0 - t) * a + t * b; }

}  // namespace

double trilinearValue(const Volume<double>& v, const Levels3& levels, glm::dvec3 p) {
  const Cell c = cellOf(levels, p);
  auto at = [&](int dx, int dy, int dz) { return v.at(c.i0[0] + dx, c.i0[1] + dy, c.i0[2] + dz); };
  // The same operations, in the same order, as trilinear(): identical values.
  const double c00 = lerp(at(0, 0, 0), at(1, 0, 0), c.w[0]), c10 = lerp(at(0, 1, 0), at(1, 1, 0), c.w[0]);
  const double c01 = lerp(at(0, 0, 1), at(1, 0, 1), c.w[0]), c11 = lerp(at(0, 1, 1), at(1, 1, 1), c.w[0]);
  return lerp(lerp(c00, c10, c.w[1]), lerp(c01, c11, c.w[1]), c.w[2]);
}

ValueGradient trilinear(const Volume<double>& v, const Levels3& levels, glm::dvec3 p) {
  const Cell cell = cellOf(levels, p);
  const int* i0 = cell.i0;
  const double* w = cell.w;
  double scale[3];
  for (int a = 0; a < 3; ++a) scale[a] = 1 << levels[a];
  auto at = [&](int dx, int dy, int dz) { return v.at(i0[0] + dx, i0[1] + dy, i0[2] + dz); };
  // Corner values, x first.
  const double c00 = lerp(at(0, 0, 0), at(1, 0, 0), w[0]);
  const double c10 = lerp(at(0, 1, 0), at(1, 1, 0), w[0]);
  const double c01 = lerp(at(0, 0, 1), at(1, 0, 1), w[0]);
  const double c11 = lerp(at(0, 1, 1), at(1, 1, 1), w[0]);
  const double c0 = lerp(c00, c10, w[1]), c1 = lerp(c01, c11, w[1]);
  ValueGradient out;
  out.value = lerp(c0, c1, w[2]);
  // Derivatives of the trilinear cell function: difference along the axis, interpolated in the others.
  auto dx = [&](int y, int z) { return at(1, y, z) - at(0, y, z); };
  const double gx = lerp(lerp(dx(0, 0), dx(1, 0), w[1]), lerp(dx(0, 1), dx(1, 1), w[1]), w[2]);
  const double gy = lerp(c10 - c00, c11 - c01, w[2]);
  out.gradient = {scale[0] * gx, scale[1] * gy, scale[2] * (c1 - c0)};
  return out;
}

double Combination::value(glm::dvec3 x) const {
  double sum = 0.0;
  for (const ComponentGrid& g : grids_) sum += g.coefficient * trilinearValue(g.values, g.levels, x);
  return sum;
}

ValueGradient Combination::valueGradient(glm::dvec3 x) const {
  ValueGradient sum;
  for (const ComponentGrid& g : grids_) {
    const ValueGradient t = trilinear(g.values, g.levels, x);
    sum.value += g.coefficient * t.value;
    sum.gradient += static_cast<double>(g.coefficient) * t.gradient;
  }
  return sum;
}

}  // namespace voxref::ref
