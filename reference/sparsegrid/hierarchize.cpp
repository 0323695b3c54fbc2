#include "reference/sparsegrid/hierarchize.h"

#include <stdexcept>
#include <string>

namespace voxref::ref {
namespace {

enum class Direction { Hierarchize, Dehierarchize };

// Calls fn(flatIndex, lattice) for every point of subspace `s`.
template <class Fn>
void forEachPoint(const SubspaceSet& set, const Subspace& s, Fn&& fn) {
  const int n = set.spec().level;
  std::size_t idx = s.offset;
  for (int k = 0; k < s.count[2]; ++k)
    for (int j = 0; j < s.count[1]; ++j)
      for (int i = 0; i < s.count[0]; ++i, ++idx)
        fn(idx, std::array<std::int64_t, 3>{latticeCoordinate(n, s.levels[0], i), latticeCoordinate(n, s.levels[1], j),
                                            latticeCoordinate(n, s.levels[2], k)});
}

void transformSparse(const SubspaceSet& set, std::vector<double>& u, Direction dir) {
  if (u.size() != set.pointCount())
    throw std::invalid_argument("sparse grid has " + std::to_string(set.pointCount()) + " points, values have " +
                                std::to_string(u.size()));
  const int n = set.spec().level;
  const bool boundary = set.spec().boundary;
  const std::int64_t full = std::int64_t{1} << n;
  auto valueAt = [&](std::array<std::int64_t, 3> lattice) -> double {
    for (int d = 0; d < 3; ++d)
      if (!boundary && (lattice[d] == 0 || lattice[d] == full)) return 0.0;
    const auto p = set.pointAt(lattice);
    if (!p) throw std::logic_error("hierarchical parent missing from the sparse grid");
    return u[*p];
  };
  for (int d = 0; d < 3; ++d) {
    // Hierarchize finest level first (parents still hold their values along d); dehierarchize
    // coarsest first (parents already hold their values again).
    for (int step = 0; step < n; ++step) {
      const int level = dir == Direction::Hierarchize ? n - step : 1 + step;
      for (const Subspace& s : set.subspaces()) {
        if (s.levels[d] != level) continue;
        const std::int64_t h = std::int64_t{1} << (n - level);
        forEachPoint(set, s, [&](std::size_t idx, std::array<std::int64_t, 3> lattice) {
          auto left = lattice, right = lattice;
          left[d] -= h;
          right[d] += h;
          const double mean = 0.5 * (valueAt(left) + valueAt(right));
          u[idx] = dir == Direction::Hierarchize ? u[idx] - mean : u[idx] + mean;
        });
      }
    }
  }
}

void transformFull(Volume<double>& g, bool boundary, Direction dir) {
  const auto dims = g.dims();
  int n = 0;
  while ((1 << n) + 1 < dims[0] && n < 30) ++n;
  if (dims[0] != (1 << n) + 1 || dims[1] != dims[0] || dims[2] != dims[0])
    throw std::invalid_argument("full grid must have 2^n + 1 points on every axis, got " + std::to_string(dims[0]) +
                                "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]));
  const int last = dims[0] - 1;
  const std::size_t side = static_cast<std::size_t>(dims[0]);
  const std::size_t stride[3] = {1, side, side * side};
  auto onBoundary = [&](std::size_t idx) {
    for (int a = 0; a < 3; ++a) {
      const std::size_t c = (idx / stride[a]) % side;
      if (c == 0 || c == static_cast<std::size_t>(last)) return true;
    }
    return false;
  };
  std::vector<double>& u = g.data();
  auto value = [&](std::size_t idx) { return !boundary && onBoundary(idx) ? 0.0 : u[idx]; };
  for (int d = 0; d < 3; ++d) {
    const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;  // the two other axes
    for (int step = 0; step < n; ++step) {
      const int level = dir == Direction::Hierarchize ? n - step : 1 + step;
      const int h = 1 << (n - level);
      for (int c2 = 0; c2 <= last; ++c2)
        for (int c1 = 0; c1 <= last; ++c1)
          for (int cd = h; cd < last; cd += 2 * h) {  // odd multiples of h
            const std::size_t idx = cd * stride[d] + c1 * stride[e1] + c2 * stride[e2];
            const double mean = 0.5 * (value(idx - h * stride[d]) + value(idx + h * stride[d]));
            u[idx] = dir == Direction::Hierarchize ? u[idx] - mean : u[idx] + mean;
          }
    }
  }
  if (!boundary)  // without boundary points the boundary carries neither value nor surplus
    for (std::size_t idx = 0; idx < u.size(); ++idx)
      if (onBoundary(idx)) u[idx] = 0.0;
}

}  // namespace

void hierarchizeSparse(const SubspaceSet& set, std::vector<double>& values) {
  transformSparse(set, values, Direction::Hierarchize);
}
void dehierarchizeSparse(const SubspaceSet& set, std::vector<double>& values) {
  transformSparse(set, values, Direction::Dehierarchize);
}
void hierarchizeFullGrid(Volume<double>& grid, bool boundary) { transformFull(grid, boundary, Direction::Hierarchize); }
void dehierarchizeFullGrid(Volume<double>& grid, bool boundary) {
  transformFull(grid, boundary, Direction::Dehierarchize);
}

}  // namespace voxref::ref
