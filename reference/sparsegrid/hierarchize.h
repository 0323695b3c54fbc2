// Hierarchization: nodal values -> hierarchical surpluses (the coefficients c of eq. 3), and
// its inverse, on full grids and directly on sparse grids.
//
// Along one axis, the surplus of a point of level l >= 1 is its value minus the mean of its two
// hierarchical parents x -+ 2^-l (the linear interpolant of the coarser levels); level-0
// (boundary) points keep their value. In 3D the 1D operator is applied axis after axis
// (x, then y, then z) on the partially transformed values: the tensor-product ("unidirectional")
// hierarchization. Each update is the fixed-order double expression
//     u[p] = u[p] - 0.5 * (u[left] + u[right]),
// so the full-grid and the sparse-grid versions give bit-identical surpluses on the points they
// share: a sparse grid's subspace set is closed under taking parents, so every pole update reads
// the same operands in both.
//
// Zero boundary: boundary values are taken as 0 (the function is assumed to vanish there).
#pragma once

#include <vector>

#include "reference/common/volume.h"
#include "reference/sparsegrid/subspaces.h"

namespace voxref::ref {

// In place on values in the flat layout of `set` (size must equal set.pointCount(), else
// std::invalid_argument). Never allocates a full grid: works for levels 11 and 12.
void hierarchizeSparse(const SubspaceSet& set, std::vector<double>& values);
void dehierarchizeSparse(const SubspaceSet& set, std::vector<double>& values);

// In place on a (2^n + 1)^3 full grid (std::invalid_argument for other sizes).
void hierarchizeFullGrid(Volume<double>& grid, bool boundary);
void dehierarchizeFullGrid(Volume<double>& grid, bool boundary);

}  // namespace voxref::ref
