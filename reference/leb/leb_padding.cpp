#include "reference/leb/leb_padding.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace voxref::ref {

LebPadding::LebPadding(const LebGrid& grid, const Dims3& dims, int components)
    : grid_(grid), dims_(dims), components_(components) {
  values_.reserve(static_cast<std::size_t>(shellPoints(grid, dims)));
}

const LebValues& LebPadding::at(const GridPoint& q) const {
  const LebValues* v = values_.find(grid_.linearIndex(q));
  if (!v) throw std::logic_error("LEB padding point " + pointText(q) + " is outside the shell a prediction can reach");
  return *v;
}

std::uint64_t LebPadding::shellPoints(const LebGrid& grid, const Dims3& dims) {
  const int side = grid.side();
  std::uint64_t n = 0;
  for (unsigned c = 0; c < 8; ++c)
    n += !insideVolume({(c & 1) ? side : 0, (c & 2) ? side : 0, (c & 4) ? side : 0}, dims);
  // Per level and orientation: the points with coordinates first + 2h c up to the shell's last,
  // less those inside the volume (up to X - 1).
  const auto count = [](int first, int last, int step) -> std::uint64_t {
    return last < first ? 0 : static_cast<std::uint64_t>((last - first) / step) + 1;
  };
  for (int level = 0; level < grid.levelCount(); ++level) {
    const int h = 1 << (grid.k - 1 - level / 3), oddCount = 3 - level % 3;
    for (unsigned odd = 1; odd < 8; ++odd) {
      if (std::popcount(odd) != oddCount) continue;
      std::uint64_t all = 1, in = 1;
      for (int a = 0; a < 3; ++a) {
        const int first = ((odd >> a) & 1u) ? h : 0;
        all *= count(first, std::min(side, dims[a] + h - 2), 2 * h);
        in *= count(first, dims[a] - 1, 2 * h);
      }
      n += all - in;
    }
  }
  return n;
}

}  // namespace voxref::ref
