// The combination technique (Teitzel et al. 1999, section 3, eq. 11): the sparse-grid
// interpolant of level n as a signed sum of trilinear interpolants on anisotropic full grids,
//     f_n = sum_{|l| = n+2} f_l  -  2 sum_{|l| = n+1} f_l  +  sum_{|l| = n} f_l,   l_d >= 1,
// where grid l has (2^l1 + 1) x (2^l2 + 1) x (2^l3 + 1) nodes, all of them sparse-grid points,
// holding the sparse grid's nodal values. There are 3/2 n (n - 1) + 1 grids (eq. 13).
//
// Grid order is the paper's (pseudo code of createTextures): first the positive grids with
// |l| = n + 2, then those with |l| = n, then the negative grids with |l| = n + 1; within a group
// lexicographic in (l1, l2). n+ = number of positive grids.
//
// Exactness: double precision; each trilinear interpolant is (1 - w) a + w b along x, then y,
// then z; the grids are summed in grid order. Deterministic. Equal to direct sparse-grid
// interpolation in exact arithmetic at every point (gradients with the same right-sided cell
// convention, see sparse_grid.h).
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/common/volume.h"
#include "reference/sparsegrid/sparse_grid.h"

namespace voxref::ref {

struct ComponentGrid {
  Levels3 levels{};
  int coefficient = 0;    // +1 or -2
  Volume<double> values;  // (2^l1 + 1) x (2^l2 + 1) x (2^l3 + 1) nodal values
};

// Levels and coefficients only (no values): cheap, for counting and memory tables.
struct ComponentGridShape {
  Levels3 levels{};
  int coefficient = 0;
};
std::vector<ComponentGridShape> combinationGridShapes(int level);

class Combination {
 public:
  // Copies the sparse grid's nodal values onto every component grid.
  explicit Combination(const SparseGrid& grid);

  int level() const { return level_; }
  bool boundary() const { return boundary_; }
  const std::vector<ComponentGrid>& grids() const { return grids_; }
  int positiveCount() const { return positiveCount_; }  // n+ of the paper

  // Value and gradient at x in [0,1]^3 (clamped), eq. 11.
  double value(glm::dvec3 x) const;
  ValueGradient valueGradient(glm::dvec3 x) const;

 private:
  int level_;
  bool boundary_;
  int positiveCount_ = 0;
  std::vector<ComponentGrid> grids_;
};

// Trilinear interpolation of one grid's node values on [0,1]^3 (cell i0 = min(floor(x N), N - 1),
// N = 2^l per axis), value and gradient, in double.
ValueGradient trilinear(const Volume<double>& values, const Levels3& levels, glm::dvec3 x);
// The value alone, bit-identical to trilinear(...).value.
double trilinearValue(const Volume<double>& values, const Levels3& levels, glm::dvec3 x);

}  // namespace voxref::ref
