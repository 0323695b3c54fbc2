// The hierarchical subspaces of a 3D sparse grid of level n (Teitzel et al. 1999, section 2).
//
// Zero boundary (the paper's text, eq. 6): subspaces S(l1,l2,l3) with l_d >= 1 and
// l1 + l2 + l3 <= n + 2. Subspace level l_d >= 1 has 2^(l_d - 1) points along axis d, at
// x = (2j + 1) / 2^l_d.
//
// With boundary points: per-axis level 0 is added, holding the two boundary hats (points x = 0
// and x = 1, basis 1 - x and x). A subspace is kept when sum_d max(l_d, 1) <= n + 2: exactly the
// union of the nodes of the combination technique's component grids (eq. 11) when those grids
// include their boundary nodes. `tests/reference/sparsegrid/subspaces_test.cpp` checks both
// counts against an independent count of that union.
//
// Points of every subspace are stored in one flat array, subspace after subspace, x fastest
// within a subspace (the paper's "flat arrays per subspace", section 5.2). A point is addressed
// either by (subspace, index) or by its coordinates on the level-n lattice: integers a in
// [0, 2^n] per axis with x = a / 2^n.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace voxref::ref {

inline constexpr int kMinSparseLevel = 1;
inline constexpr int kMaxSparseLevel = 12;

struct SparseGridSpec {
  int level = 5;         // n, 1..12
  bool boundary = true;  // true: with boundary points; false: zero boundary
};

using Levels3 = std::array<int, 3>;

struct Subspace {
  Levels3 levels{};            // per-axis level (0 = boundary level)
  std::array<int, 3> count{};  // points per axis: 2 for level 0, 2^(l-1) otherwise
  std::size_t offset = 0;      // first point in the flat array
  std::size_t size() const { return static_cast<std::size_t>(count[0]) * count[1] * count[2]; }
};

// Points per axis of a subspace level, and the lattice coordinate (on the level-n lattice) of
// point j of that level.
int pointsOnLevel(int level);
std::int64_t latticeCoordinate(int n, int level, int j);

// Level and index along one axis of lattice coordinate a in [0, 2^n] (inverse of the above).
struct AxisPoint {
  int level;
  int index;
};
AxisPoint axisPointOf(int n, std::int64_t a);

class SubspaceSet {
 public:
  // Throws std::invalid_argument naming the bound if spec.level is outside 1..12.
  explicit SubspaceSet(SparseGridSpec spec);

  const SparseGridSpec& spec() const { return spec_; }
  const std::vector<Subspace>& subspaces() const { return subspaces_; }
  std::size_t pointCount() const { return pointCount_; }

  // Index of the subspace with these levels, if it belongs to the set.
  std::optional<std::size_t> find(const Levels3& levels) const;
  // Flat index of the point at lattice coordinates (a, b, c), if it belongs to the set.
  std::optional<std::size_t> pointAt(const std::array<std::int64_t, 3>& lattice) const;

 private:
  SparseGridSpec spec_;
  std::vector<Subspace> subspaces_;
  std::vector<int> lookup_;  // (n+1)^3 table of subspace index + 1, 0 = absent
  std::size_t pointCount_ = 0;
};

}  // namespace voxref::ref
