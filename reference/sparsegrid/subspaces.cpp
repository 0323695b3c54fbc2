#include "reference/sparsegrid/subspaces.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace voxref::ref {

int pointsOnLevel(int level) { return level == 0 ? 2 : 1 << (level - 1); }

std::int64_t latticeCoordinate(int n, int level, int j) {
  if (level == 0) return static_cast<std::int64_t>(j) << n;
  return static_cast<std::int64_t>(2 * j + 1) << (n - level);
}

AxisPoint axisPointOf(int n, std::int64_t a) {
  const std::int64_t full = std::int64_t{1} << n;
  if (a == 0) return {0, 0};
  if (a == full) return {0, 1};
  const int tz = std::countr_zero(static_cast<std::uint64_t>(a));
  return {n - tz, static_cast<int>((a >> tz) >> 1)};
}

SubspaceSet::SubspaceSet(SparseGridSpec spec) : spec_(spec) {
  const int n = spec.level;
  if (n < kMinSparseLevel || n > kMaxSparseLevel)
    throw std::invalid_argument("sparse grid level " + std::to_string(n) + " is outside " +
                                std::to_string(kMinSparseLevel) + ".." + std::to_string(kMaxSparseLevel));
  const int lo = spec.boundary ? 0 : 1;
  const int side = n + 1;
  lookup_.assign(static_cast<std::size_t>(side) * side * side, 0);
  // Order: by subspace level sum (coarse first), then lexicographic (l1, l2, l3). Any fixed
  // order would do; this one makes coarser data come first.
  for (int sum = 3; sum <= n + 2; ++sum)
    for (int l1 = lo; l1 <= n; ++l1)
      for (int l2 = lo; l2 <= n; ++l2)
        for (int l3 = lo; l3 <= n; ++l3) {
          if (std::max(l1, 1) + std::max(l2, 1) + std::max(l3, 1) != sum) continue;
          Subspace s;
          s.levels = {l1, l2, l3};
          s.count = {pointsOnLevel(l1), pointsOnLevel(l2), pointsOnLevel(l3)};
          s.offset = pointCount_;
          pointCount_ += s.size();
          subspaces_.push_back(s);
          lookup_[static_cast<std::size_t>(l1) + side * (l2 + static_cast<std::size_t>(side) * l3)] =
              static_cast<int>(subspaces_.size());
        }
}

std::optional<std::size_t> SubspaceSet::find(const Levels3& l) const {
  const int side = spec_.level + 1;
  for (int d = 0; d < 3; ++d)
    if (l[d] < 0 || l[d] >= side) return std::nullopt;
  const int v = lookup_[static_cast<std::size_t>(l[0]) + side * (l[1] + static_cast<std::size_t>(side) * l[2])];
  if (v == 0) return std::nullopt;
  return static_cast<std::size_t>(v - 1);
}

std::optional<std::size_t> SubspaceSet::pointAt(const std::array<std::int64_t, 3>& lattice) const {
  const std::int64_t full = std::int64_t{1} << spec_.level;
  Levels3 levels{};
  std::array<int, 3> index{};
  for (int d = 0; d < 3; ++d) {
    if (lattice[d] < 0 || lattice[d] > full) return std::nullopt;
    const AxisPoint p = axisPointOf(spec_.level, lattice[d]);
    levels[d] = p.level;
    index[d] = p.index;
  }
  const auto s = find(levels);
  if (!s) return std::nullopt;
  const Subspace& sub = subspaces_[*s];
  return sub.offset + static_cast<std::size_t>(index[0]) +
         static_cast<std::size_t>(sub.count[0]) * (index[1] + static_cast<std::size_t>(sub.count[1]) * index[2]);
}

}  // namespace voxref::ref
