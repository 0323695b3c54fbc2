#include "reference/sparsegrid/sparse_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/common/rounding.h"
#include "reference/sparsegrid/hierarchize.h"

namespace voxref::ref {

HatTerms hatTermsAt(int level, double x) {
  HatTerms h;
  if (level == 0) {
    h.count = 2;
    h.terms[0] = {0, 1.0 - x, -1.0};
    h.terms[1] = {1, x, 1.0};
    return h;
  }
  // Eq. 2: centre m = (2j + 1) h_l, support [m - h_l, m + h_l], h_l = 2^-l.
  const double scaled = scaleByPowerOfTwo(x, level);  // x * 2^l, exact
  const int last = (1 << (level - 1)) - 1;
  const int j = std::clamp(static_cast<int>(std::floor(0.5 * scaled)), 0, last);
  const double centre = 2.0 * j + 1.0;
  const double value = std::max(0.0, 1.0 - std::fabs(scaled - centre));
  const double steep = powerOfTwo(level);
  h.count = 1;
  h.terms[0] = {j, value, scaled < centre ? steep : -steep};
  return h;
}

SparseGrid::SparseGrid(SparseGridSpec spec, std::vector<double> nodal) : set_(spec), nodal_(std::move(nodal)) {
  if (nodal_.size() != set_.pointCount())
    throw std::invalid_argument("sparse grid of level " + std::to_string(spec.level) + " has " +
                                std::to_string(set_.pointCount()) + " points, got " + std::to_string(nodal_.size()) +
                                " values");
  surplus_ = nodal_;
  hierarchizeSparse(set_, surplus_);
}

SparseGrid SparseGrid::fromNodalValues(SparseGridSpec spec, std::vector<double> nodal) {
  return SparseGrid(spec, std::move(nodal));
}

SparseGrid SparseGrid::fromField(SparseGridSpec spec, const Field& field) {
  const SubspaceSet set(spec);
  const int n = spec.level;
  std::vector<double> nodal(set.pointCount());
  for (const Subspace& s : set.subspaces()) {
    std::size_t idx = s.offset;
    for (int k = 0; k < s.count[2]; ++k)
      for (int j = 0; j < s.count[1]; ++j)
        for (int i = 0; i < s.count[0]; ++i, ++idx) {
          const double x = std::ldexp(static_cast<double>(latticeCoordinate(n, s.levels[0], i)), -n);
          const double y = std::ldexp(static_cast<double>(latticeCoordinate(n, s.levels[1], j)), -n);
          const double z = std::ldexp(static_cast<double>(latticeCoordinate(n, s.levels[2], k)), -n);
          nodal[idx] = field(x, y, z);
        }
  }
  return SparseGrid(spec, std::move(nodal));
}

double SparseGrid::nodalAt(const std::array<std::int64_t, 3>& lattice) const {
  const std::int64_t full = std::int64_t{1} << spec().level;
  if (!spec().boundary)
    for (std::int64_t c : lattice)
      if (c == 0 || c == full) return 0.0;
  const auto p = set_.pointAt(lattice);
  if (!p)
    throw std::out_of_range("lattice point (" + std::to_string(lattice[0]) + ", " + std::to_string(lattice[1]) + ", " +
                            std::to_string(lattice[2]) + ") is not a point of this sparse grid");
  return nodal_[*p];
}

template <bool WithGradient>
ValueGradient SparseGrid::evaluate(glm::dvec3 p) const {
  const int n = spec().level;
  const double c[3] = {std::clamp(p.x, 0.0, 1.0), std::clamp(p.y, 0.0, 1.0), std::clamp(p.z, 0.0, 1.0)};
  // Hat terms per axis and level, computed once per point.
  std::array<std::array<HatTerms, kMaxSparseLevel + 1>, 3> hats;
  for (int a = 0; a < 3; ++a)
    for (int l = 0; l <= n; ++l) hats[a][l] = hatTermsAt(l, c[a]);
  ValueGradient out;
  for (const Subspace& s : set_.subspaces()) {
    const HatTerms& hx = hats[0][s.levels[0]];
    const HatTerms& hy = hats[1][s.levels[1]];
    const HatTerms& hz = hats[2][s.levels[2]];
    for (int tz = 0; tz < hz.count; ++tz)
      for (int ty = 0; ty < hy.count; ++ty)
        for (int tx = 0; tx < hx.count; ++tx) {
          const HatTerm& X = hx.terms[tx];
          const HatTerm& Y = hy.terms[ty];
          const HatTerm& Z = hz.terms[tz];
          const double coef = surplus_[s.offset + static_cast<std::size_t>(X.index) +
                                       static_cast<std::size_t>(s.count[0]) *
                                           (Y.index + static_cast<std::size_t>(s.count[1]) * Z.index)];
          out.value += coef * (X.value * Y.value * Z.value);
          if constexpr (WithGradient) {
            out.gradient.x += coef * (X.slope * Y.value * Z.value);
            out.gradient.y += coef * (X.value * Y.slope * Z.value);
            out.gradient.z += coef * (X.value * Y.value * Z.slope);
          }
        }
  }
  return out;
}

double SparseGrid::value(glm::dvec3 x) const { return evaluate<false>(x).value; }
ValueGradient SparseGrid::valueGradient(glm::dvec3 x) const { return evaluate<true>(x); }

}  // namespace voxref::ref
