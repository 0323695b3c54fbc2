// A 3D sparse grid with its nodal values and hierarchical surpluses in flat per-subspace arrays,
// and direct sparse-grid interpolation of value and gradient (Teitzel et al. 1999, eq. 2, 3, 7
// and section 5.2: one hat function per subspace and axis is non-zero at a point; two on a
// boundary level, whose basis is 1 - x and x).
//
// Exactness: double precision, fixed summation order (subspace order of SubspaceSet, then the
// boundary hats left before right); deterministic. Gradients use the right-sided derivative at
// a kink (the cell to the right of a node; at x = 1 the cell to the left), the same convention
// as the combination technique's trilinear cells, so both agree wherever exact arithmetic says
// they must.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/common/fields.h"
#include "reference/sparsegrid/subspaces.h"

namespace voxref::ref {

struct ValueGradient {
  double value = 0.0;
  glm::dvec3 gradient{0.0};
};

class SparseGrid {
 public:
  // Samples `field` at every sparse-grid point and hierarchizes on the sparse grid itself: no
  // full grid is allocated at any level (levels 11 and 12 included). Zero-boundary grids do not
  // sample the boundary: the field is assumed to vanish there.
  static SparseGrid fromField(SparseGridSpec spec, const Field& field);
  // From nodal values in the flat layout of SubspaceSet(spec) (std::invalid_argument on size).
  static SparseGrid fromNodalValues(SparseGridSpec spec, std::vector<double> nodal);

  const SparseGridSpec& spec() const { return set_.spec(); }
  const SubspaceSet& subspaces() const { return set_; }
  const std::vector<double>& nodalValues() const { return nodal_; }
  const std::vector<double>& surpluses() const { return surplus_; }

  // Nodal value at lattice coordinates (a, b, c) in [0, 2^n]. Zero-boundary grids return 0 on
  // the boundary. Throws std::out_of_range for a point that is not in the grid.
  double nodalAt(const std::array<std::int64_t, 3>& lattice) const;

  // Direct sparse-grid interpolation (eq. 7) at x in [0,1]^3 (coordinates are clamped).
  double value(glm::dvec3 x) const;
  ValueGradient valueGradient(glm::dvec3 x) const;

 private:
  SparseGrid(SparseGridSpec spec, std::vector<double> nodal);
  template <bool WithGradient>
  ValueGradient evaluate(glm::dvec3 x) const;

  SubspaceSet set_;
  std::vector<double> nodal_;
  std::vector<double> surplus_;
};

// The non-zero hat functions of one level along one axis at coordinate x in [0, 1]: one for
// levels >= 1, two (1 - x and x) for the boundary level 0. `slope` is the right-sided
// derivative (left-sided at x = 1).
struct HatTerm {
  int index;
  double value;
  double slope;
};
struct HatTerms {
  int count = 0;
  HatTerm terms[2];
};
HatTerms hatTermsAt(int level, double x);

}  // namespace voxref::ref
