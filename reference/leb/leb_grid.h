// The longest-edge-bisection (LEB) hierarchy on a (2^k + 1)^3 grid, in closed form (Gregorski,
// Senecal, Duchaineau, Joy 2004, section 2; diamonds after Gregorski et al. 2002).
//
// The root cube [0, N]^3, N = 2^k, is cut into six tetrahedra around its major diagonal; every
// tetrahedron is bisected at the midpoint of its longest edge. All tetrahedra sharing a split
// edge form a diamond, refined together by inserting its *split vertex*, the edge's midpoint.
// Every grid point except the eight root corners is the split vertex of exactly one diamond, so a
// diamond is named by its split vertex.
//
// A point p that is not a corner has a scale h = 2^s (the largest power of two dividing all its
// coordinates, s < k) and odd axes (those where p / h is odd). The number of odd axes is its phase
// (the paper's Figure 2):
//   phase 2  three odd axes   split edge a diagonal of the cube of side 2h centred at p  (6 tets)
//   phase 1  two odd axes     split edge a diagonal of the face square of side 2h       (4 tets)
//   phase 0  one odd axis     split edge the cube edge of length 2h through p           (8 tets)
// Refinement inserts, per scale from coarse to fine, phase 2, then 1, then 0 points: the level of
// p is 3 (k - 1 - s) + (2 - phase), in [0, 3k); corners have level -1. The split edge of p runs
// through p towards the centre of the cube of side 4h that contains p (the "parent cube"): its
// endpoints are p +- h sigma, sigma_a = sign(centre_a - p_a) on the odd axes. Both endpoints are
// coarser than p. The unit tests derive all of this again by bisecting tetrahedra (brute force).
//
// All functions are exact integer arithmetic and safe for any k in [0, kMaxLebK]; points outside
// the grid or corners passed where a split vertex is needed throw std::invalid_argument.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace voxref::ref {

using GridPoint = std::array<int, 3>;

inline constexpr int kMaxLebK = 11;  // 2049^3 points: the codec and its stream (FORMAT.md)
// Random access and the isosurface system name a grid point by a 32-bit index (LebReader's memo
// keys, DiamondId, the marching-tetrahedra vertex keys hold linear indices below 2^31): they take
// grids up to k = 10, 1025^3 points.
inline constexpr int kMaxIndexedLebK = 10;

struct LebGrid {
  int k = 0;  // N = 2^k cells per axis, N + 1 points per axis

  int side() const { return 1 << k; }
  int pointsPerAxis() const { return side() + 1; }
  std::uint64_t pointCount() const {
    const auto n = static_cast<std::uint64_t>(pointsPerAxis());
    return n * n * n;
  }
  int levelCount() const { return 3 * k; }
  bool contains(const GridPoint& p) const {
    // One unsigned comparison per axis: a negative coordinate wraps above the side.
    const auto n = static_cast<unsigned>(side());
    return static_cast<unsigned>(p[0]) <= n && static_cast<unsigned>(p[1]) <= n && static_cast<unsigned>(p[2]) <= n;
  }
  // x + (N + 1) (y + (N + 1) z)
  std::uint64_t linearIndex(const GridPoint& p) const {
    const auto n = static_cast<std::uint64_t>(pointsPerAxis());
    return static_cast<std::uint64_t>(p[0]) +
           n * (static_cast<std::uint64_t>(p[1]) + n * static_cast<std::uint64_t>(p[2]));
  }
  // The inverse of linearIndex.
  GridPoint pointAt(std::uint64_t linear) const {
    const auto n = static_cast<std::uint64_t>(pointsPerAxis());
    return {static_cast<int>(linear % n), static_cast<int>(linear / n % n), static_cast<int>(linear / (n * n))};
  }
};

// Throws std::invalid_argument unless 0 <= k <= kMaxLebK.
LebGrid makeLebGrid(int k);
// Throws std::invalid_argument, naming `what`, for a grid past kMaxIndexedLebK.
void requireIndexedGrid(const LebGrid& g, const char* what);
// The smallest grid whose (2^k + 1)^3 points cover `dims` (each extent >= 1).
LebGrid lebGridCovering(const std::array<int, 3>& dims);

// "(x, y, z)", for the messages that name a point.
std::string pointText(const GridPoint& p);

struct LebPointClass {
  int level = -1;        // -1 for a root corner
  int scaleLog2 = 0;     // s, the point's scale is h = 2^s (k for a corner)
  int phase = 0;         // the paper's numbering: odd axes - 1 (2 cube diagonal, 1 face diagonal, 0 cube edge)
  unsigned oddAxes = 0;  // bit a set when p_a / h is odd
};
LebPointClass classifyPoint(const LebGrid& g, const GridPoint& p);
bool isRootCorner(const LebGrid& g, const GridPoint& p);

struct SplitEdge {
  GridPoint a, b;  // a is the endpoint towards the parent cube's centre
};
// The split edge of the diamond whose split vertex is p (p not a corner).
SplitEdge splitEdge(const LebGrid& g, const GridPoint& p);
// The same closed form without checks, given p's scale and odd axes (classifyPoint), for the
// codec's inner loops: on an odd axis p_a is h or 3h modulo 4h, and the parent cube's centre is
// at 2h, so the edge runs up from h and down from 3h.
// splitEdgeSigma gives, on an odd axis a, the signed step from p to endpoint a.
[[gnu::always_inline]] inline int splitEdgeSigma(const GridPoint& p, int scaleLog2, int a) {
  const int h = 1 << scaleLog2;
  return ((p[a] >> (scaleLog2 + 1)) & 1) ? -h : h;
}
[[gnu::always_inline]] inline SplitEdge splitEdgeOf(const GridPoint& p, int scaleLog2, unsigned oddAxes) {
  SplitEdge e{p, p};
  for (int a = 0; a < 3; ++a)
    if ((oddAxes >> a) & 1) {
      const int sigma = splitEdgeSigma(p, scaleLog2, a);
      e.a[a] = p[a] + sigma;
      e.b[a] = p[a] - sigma;
    }
  return e;
}

// Up to eight grid points held in place: a diamond's ring, parents or children, which refinement
// asks for millions of times a frame (a vector would allocate every time). Ranges over the points.
class DiamondPoints {
 public:
  void push_back(const GridPoint& p) {
    if (n_ == points_.size()) throw std::logic_error("DiamondPoints: more than eight points");
    points_[n_++] = p;
  }
  const GridPoint* begin() const { return points_.data(); }
  const GridPoint* end() const { return points_.data() + n_; }
  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  const GridPoint& operator[](std::size_t i) const { return points_[i]; }
  // Keeps the points for which keep(p) holds, in order.
  template <class Keep>
  void keepIf(Keep&& keep) {
    std::size_t m = 0;
    for (std::size_t i = 0; i < n_; ++i)
      if (keep(points_[i])) points_[m++] = points_[i];
    n_ = m;
  }

 private:
  std::array<GridPoint, 8> points_{};
  std::size_t n_ = 0;
};

// The vertices around the split edge (the other vertices of the diamond's tetrahedra), in the
// full diamond; those outside the grid are dropped (a diamond on the boundary is a part diamond).
DiamondPoints diamondRing(const LebGrid& g, const GridPoint& p);
// The diamonds whose splitting creates this diamond's tetrahedra: the ring vertices one level
// coarser (3 for phase 2, 2 for phase 1, 4 for phase 0 inside the grid; none for the root).
DiamondPoints diamondParents(const LebGrid& g, const GridPoint& p);
// The diamonds whose tetrahedra splitting this diamond creates (6, 4, 8 inside the grid).
DiamondPoints diamondChildren(const LebGrid& g, const GridPoint& p);

}  // namespace voxref::ref
