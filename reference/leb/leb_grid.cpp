#include "reference/leb/leb_grid.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>
#include <utility>

namespace voxref::ref {
namespace {

void requireInside(const LebGrid& g, const GridPoint& p) {
  if (!g.contains(p))
    throw std::invalid_argument("point " + pointText(p) + " is outside the " + std::to_string(g.pointsPerAxis()) +
                                "^3 grid");
}

// classifyPoint for a diamond's split vertex: throws std::invalid_argument for a root corner.
LebPointClass diamondClass(const LebGrid& g, const GridPoint& p) {
  const LebPointClass c = classifyPoint(g, p);
  if (c.level < 0)
    throw std::invalid_argument("the root corner " + pointText(p) + " is not the split vertex of a diamond");
  return c;
}

// Corner m (bit a set: + h on axis a, else - h) of the cube of side 2h around p.
GridPoint cubeCorner(const GridPoint& p, int h, int m) {
  return {p[0] + ((m & 1) ? h : -h), p[1] + ((m & 2) ? h : -h), p[2] + ((m & 4) ? h : -h)};
}

void keepInside(const LebGrid& g, DiamondPoints& points) {
  points.keepIf([&](const GridPoint& q) { return g.contains(q); });
}

}  // namespace

LebGrid makeLebGrid(int k) {
  if (k < 0 || k > kMaxLebK)
    throw std::invalid_argument("LEB grid exponent " + std::to_string(k) + " is outside 0.." +
                                std::to_string(kMaxLebK) + " (at most " + std::to_string((1 << kMaxLebK) + 1) +
                                " points per axis)");
  return LebGrid{k};
}

void requireIndexedGrid(const LebGrid& g, const char* what) {
  if (g.k > kMaxIndexedLebK)
    throw std::invalid_argument(std::string(what) + " takes grids up to k = " + std::to_string(kMaxIndexedLebK) + " (" +
                                std::to_string((1 << kMaxIndexedLebK) + 1) +
                                "^3 points: it names a point by a 32-bit index); this one has k = " +
                                std::to_string(g.k) + ", " + std::to_string(g.pointsPerAxis()) + "^3 points");
}

LebGrid lebGridCovering(const std::array<int, 3>& dims) {
  const int largest = std::max({dims[0], dims[1], dims[2]});
  if (std::min({dims[0], dims[1], dims[2]}) < 1) throw std::invalid_argument("volume extents must be at least 1");
  int k = 0;
  while (k <= kMaxLebK && (1 << k) + 1 < largest) ++k;
  if (k > kMaxLebK)
    throw std::invalid_argument("a volume of " + std::to_string(largest) +
                                " samples per axis needs more than the largest LEB grid (" +
                                std::to_string((1 << kMaxLebK) + 1) + " per axis)");
  return LebGrid{k};
}

bool isRootCorner(const LebGrid& g, const GridPoint& p) {
  for (int v : p)
    if (v != 0 && v != g.side()) return false;
  return true;
}

LebPointClass classifyPoint(const LebGrid& g, const GridPoint& p) {
  requireInside(g, p);
  LebPointClass c;
  if (isRootCorner(g, p)) {
    c.scaleLog2 = g.k;
    return c;
  }
  // The scale: the largest power of two dividing every coordinate (0 is divisible by all).
  int s = g.k;
  for (int v : p)
    if (v != 0) s = std::min(s, std::countr_zero(static_cast<unsigned>(v)));
  c.scaleLog2 = s;
  for (int a = 0; a < 3; ++a)
    if ((p[a] >> s) & 1) c.oddAxes |= 1u << a;
  constexpr int kBits[8] = {0, 1, 1, 2, 1, 2, 2, 3};  // popcount of the 3-bit mask, without a libgcc call
  const int odd = kBits[c.oddAxes];
  c.phase = odd - 1;
  c.level = 3 * (g.k - 1 - s) + (3 - odd);
  return c;
}

SplitEdge splitEdge(const LebGrid& g, const GridPoint& p) {
  const LebPointClass c = diamondClass(g, p);
  return splitEdgeOf(p, c.scaleLog2, c.oddAxes);
}

DiamondPoints diamondRing(const LebGrid& g, const GridPoint& p) {
  const LebPointClass c = diamondClass(g, p);
  const int h = 1 << c.scaleLog2;
  const SplitEdge e = splitEdgeOf(p, c.scaleLog2, c.oddAxes);
  DiamondPoints ring;
  if (c.phase == 2) {
    // The other six corners of the cube of side 2h around p.
    for (int m = 0; m < 8; ++m) {
      const GridPoint q = cubeCorner(p, h, m);
      if (q != e.a && q != e.b) ring.push_back(q);
    }
  } else if (c.phase == 1) {
    // The other two corners of the face square, and the centres of the two cubes beside it.
    const int even = std::countr_zero(~c.oddAxes & 7u);
    const int u = std::countr_zero(c.oddAxes);
    GridPoint q = e.a;
    q[u] = e.b[u];
    ring.push_back(q);
    q = e.b;
    q[u] = e.a[u];
    ring.push_back(q);
    for (int d : {-h, h}) {
      q = p;
      q[even] += d;
      ring.push_back(q);
    }
  } else {
    // Around the cube edge: the four face centres beside p and the four cube centres between.
    const int odd = std::countr_zero(c.oddAxes);
    const int u = (odd + 1) % 3, v = (odd + 2) % 3;
    for (int du : {-h, 0, h})
      for (int dv : {-h, 0, h}) {
        if (du == 0 && dv == 0) continue;
        GridPoint q = p;
        q[u] += du;
        q[v] += dv;
        ring.push_back(q);
      }
  }
  keepInside(g, ring);
  return ring;
}

// The ring's points one level coarser, in the ring's order, without classifying the ring: with
// L = 3 (k - 1 - s) + 3 - odd (classifyPoint),
//   phase 2 (L = 3 (k - 1 - s)): the cube's corners are multiples of 2h, and a corner with one
//     coordinate an odd multiple of 2h is phase 0 of scale s + 1, level L - 1 (two or three odd:
//     L - 2, L - 3; none: coarser still, the split edge's end among them);
//   phase 1: the centres of the two cubes beside the face, p +- h on the even axis, have three
//     odd coordinates at scale s (phase 2, L - 1); the square's other corners are multiples of 2h;
//   phase 0: the four face centres beside p, p +- h on one of the even axes, have two odd
//     coordinates at scale s (phase 1, L - 1); the cube centres between them have three (L - 2).
// tests/reference/leb/leb_grid_test.cpp checks it against the ring filtered by level, and the
// brute-force bisection, at every point of small grids.
DiamondPoints diamondParents(const LebGrid& g, const GridPoint& p) {
  const LebPointClass c = diamondClass(g, p);
  DiamondPoints parents;
  if (c.level == 0) return parents;  // the root diamond: its ring is root corners
  const int h = 1 << c.scaleLog2;
  if (c.phase == 2) {
    for (int m = 0; m < 8; ++m) {
      const GridPoint q = cubeCorner(p, h, m);
      int odd = 0;
      for (int a = 0; a < 3; ++a) odd += (q[a] >> (c.scaleLog2 + 1)) & 1;
      if (odd == 1) parents.push_back(q);
    }
  } else if (c.phase == 1) {
    const int even = std::countr_zero(~c.oddAxes & 7u);
    for (const int d : {-h, h}) {
      GridPoint q = p;
      q[even] += d;
      if (g.contains(q)) parents.push_back(q);
    }
  } else {
    const int odd = std::countr_zero(c.oddAxes);
    const int u = (odd + 1) % 3, v = (odd + 2) % 3;
    for (const auto& [du, dv] : {std::pair{-h, 0}, std::pair{0, -h}, std::pair{0, h}, std::pair{h, 0}}) {
      GridPoint q = p;
      q[u] += du;
      q[v] += dv;
      if (g.contains(q)) parents.push_back(q);
    }
  }
  return parents;
}

DiamondPoints diamondChildren(const LebGrid& g, const GridPoint& p) {
  const LebPointClass c = diamondClass(g, p);
  const int h = 1 << c.scaleLog2;
  DiamondPoints children;
  if (c.phase == 2 || c.phase == 1) {
    // Phase 2: the six face centres of the cube of side 2h; phase 1: the four edge midpoints of
    // the face square. Both: p +- h along each odd axis.
    for (int a = 0; a < 3; ++a)
      if ((c.oddAxes >> a) & 1)
        for (int d : {-h, h}) {
          GridPoint q = p;
          q[a] += d;
          children.push_back(q);
        }
  } else if (c.scaleLog2 > 0) {
    // Phase 0: the centres of the eight cubes of side h around p (the next, finer scale).
    const int half = h / 2;
    for (int m = 0; m < 8; ++m) children.push_back(cubeCorner(p, half, m));
  }
  keepInside(g, children);
  return children;
}

std::string pointText(const GridPoint& p) {
  // Appended piece by piece: GCC 12 at -O3 warns (-Wrestrict, a false positive) on the chain of
  // operator+ that starts with a string literal.
  std::string text = "(";
  for (int a = 0; a < 3; ++a) {
    text += std::to_string(p[a]);
    text += a < 2 ? ", " : ")";
  }
  return text;
}

}  // namespace voxref::ref
