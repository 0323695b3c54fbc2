#include "reference/sparsegrid/full_grid.h"

#include <stdexcept>
#include <string>

#include "reference/sparsegrid/hierarchize.h"

namespace voxref::ref {

std::size_t fullGridBytes(int level) {
  const std::size_t side = (std::size_t{1} << level) + 1;
  return side * side * side * sizeof(double);
}

Volume<double> extractFullGrid(const SparseGrid& grid, std::size_t memoryLimitBytes) {
  const int n = grid.spec().level;
  if (fullGridBytes(n) > memoryLimitBytes)
    throw std::length_error("full grid of level " + std::to_string(n) + " needs " + std::to_string(fullGridBytes(n)) +
                            " bytes, more than the limit of " + std::to_string(memoryLimitBytes));
  const int side = (1 << n) + 1;
  Volume<double> full({side, side, side}, 0.0);
  const SubspaceSet& set = grid.subspaces();
  for (const Subspace& s : set.subspaces()) {
    std::size_t idx = s.offset;
    for (int k = 0; k < s.count[2]; ++k)
      for (int j = 0; j < s.count[1]; ++j)
        for (int i = 0; i < s.count[0]; ++i, ++idx)
          full.at(static_cast<int>(latticeCoordinate(n, s.levels[0], i)),
                  static_cast<int>(latticeCoordinate(n, s.levels[1], j)),
                  static_cast<int>(latticeCoordinate(n, s.levels[2], k))) = grid.surpluses()[idx];
  }
  dehierarchizeFullGrid(full, grid.spec().boundary);
  return full;
}

}  // namespace voxref::ref
