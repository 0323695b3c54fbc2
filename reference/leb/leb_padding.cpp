#include "reference/leb/leb_padding.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace voxref::ref {

LebPadding::LebPadding(const LebGrid& grid, const Dims3& dims, int components)
    : grid_(grid), dims_(dims), components_(components), blocks_(layout(grid, dims)) {
  entries_.resize(static_cast<std::size_t>(entryCount(blocks_)));
}

std::uint64_t LebPadding::entryCount(const std::vector<Block>& blocks) {
  std::uint64_t entries = 0;
  for (const Block& b : blocks) entries += b.count;
  return entries;
}

std::vector<LebPadding::Block> LebPadding::layout(const LebGrid& grid, const Dims3& dims) {
  if (dims[0] > grid.side() && dims[1] > grid.side() && dims[2] > grid.side()) return {};
  std::vector<Block> blocks(8 * static_cast<std::size_t>(grid.k + 1));
  std::uint64_t first = 0;
  for (int s = 0; s <= grid.k; ++s) {
    const int h = 1 << s;
    for (unsigned m = 1; m < 8; ++m) {
      Block b;
      b.first = first;
      b.count = 1;
      for (int a = 0; a < 3; ++a) {
        const int multiples = (dims[a] + h - 1) >> s;  // of h below X_a; the first past it is h times this
        if ((m >> a) & 1u) {
          // The only multiple of h in [X_a, X_a + h - 2], within the grid (the root corners, of scale
          // 2^k, are in the shell wherever they lie outside the volume).
          const int pinned = multiples << s;
          if (pinned > grid.side() || (s < grid.k && pinned > dims[a] + h - 2)) b.count = 0;
          b.pinned[static_cast<std::size_t>(a)] = pinned;
        } else {
          b.stride[static_cast<std::size_t>(a)] = b.count;
          b.count *= static_cast<std::uint64_t>(multiples);
        }
      }
      if (b.count == 0) b.stride = {0, 0, 0};
      first += b.count;
      blocks[8 * static_cast<std::size_t>(s) + m] = b;
    }
  }
  return blocks;
}

std::uint64_t LebPadding::tableBytes(const LebGrid& grid, const Dims3& dims) {
  const std::vector<Block> blocks = layout(grid, dims);
  return bytesOf(blocks.size(), entryCount(blocks));
}

void LebPadding::outsideShell(const GridPoint& q) {
  throw std::logic_error("LEB padding point " + pointText(q) + " is outside the shell a prediction can reach");
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
