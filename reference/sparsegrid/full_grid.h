// Full-grid extraction: the sparse-grid interpolant evaluated on every node of the level-n full
// grid, (2^n + 1)^3 values (Teitzel et al. 1999, section 7, "full grid extraction").
//
// Computed by placing the surpluses on the full grid (zero where the sparse grid has no point)
// and dehierarchizing: O(N^3) instead of one sparse-grid evaluation per node. Exact in the
// sense of hierarchize.h: fixed-order double updates, deterministic.
#pragma once

#include <cstddef>

#include "reference/common/volume.h"
#include "reference/sparsegrid/sparse_grid.h"

namespace voxref::ref {

// Bytes a full grid of `level` takes in doubles: (2^n + 1)^3 * 8.
std::size_t fullGridBytes(int level);

// Throws std::length_error naming the size when fullGridBytes(level) exceeds `memoryLimitBytes`
// (level 10 needs 8.6 GB, level 12 550 GB: refused by default).
Volume<double> extractFullGrid(const SparseGrid& grid, std::size_t memoryLimitBytes = std::size_t{4} << 30);

}  // namespace voxref::ref
