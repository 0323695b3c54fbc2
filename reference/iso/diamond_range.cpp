#include "reference/iso/diamond_range.h"

#include <map>
#include <stdexcept>

namespace voxref::ref {
namespace {

// Walks the hierarchy below a point with residues r in a grid of side 16 (far enough from its
// faces that nothing is clipped) and records what it reads, relative to the point.
FinestStencil deriveStencil(const std::array<int, 3>& r) {
  const LebGrid g = makeLebGrid(4);
  const GridPoint p{8 + r[0], 8 + r[1], 8 + r[2]};
  FinestStencil s;
  std::map<std::array<int, 3>, std::uint8_t> index;
  auto at = [&](const GridPoint& q) {
    const std::array<int, 3> o{q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    for (int a = 0; a < 3; ++a)
      if (std::abs(o[static_cast<std::size_t>(a)]) > kFinestStencilReach)
        throw std::logic_error("diamond_range: a stencil reaches beyond kFinestStencilReach");
    const auto [it, added] = index.emplace(o, static_cast<std::uint8_t>(s.offsets.size()));
    if (added) s.offsets.push_back(o);
    return it->second;
  };
  std::map<std::array<std::uint8_t, 3>, bool> edges;
  forDiamondAndDescendants(
      g, p, [&](const GridPoint& q) { at(q); },
      [&](const GridPoint& x, const GridPoint& a, const GridPoint& b) {
        const std::array<std::uint8_t, 3> e{at(x), at(a), at(b)};
        if (edges.emplace(e, true).second) s.edges.push_back(e);
      });
  if (s.offsets.size() > 125) throw std::logic_error("diamond_range: a stencil has more than 125 points");
  return s;
}

}  // namespace

const FinestStencil& finestStencil(const std::array<int, 3>& residues) {
  static const std::array<FinestStencil, 64> stencils = [] {
    std::array<FinestStencil, 64> all;
    for (int i = 0; i < 64; ++i) {
      const std::array<int, 3> r{i & 3, (i >> 2) & 3, i >> 4};
      if ((r[0] | r[1] | r[2]) & 1) all[static_cast<std::size_t>(i)] = deriveStencil(r);
    }
    return all;
  }();
  return stencils[static_cast<std::size_t>(residues[0] + 4 * residues[1] + 16 * residues[2])];
}

}  // namespace voxref::ref
