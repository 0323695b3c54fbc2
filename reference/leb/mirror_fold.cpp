// Mirror folds (mirror_fold.h; FORMAT.md beside this file, "Mirrored streams").
#include "reference/leb/mirror_fold.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace voxref::ref {
namespace {

constexpr const char* kAxisName[3] = {"x", "y", "z"};
// The search keeps a plane with at most one differing point in this many mirrored points.
constexpr std::uint64_t kSearchShare = 4 * kLebMirrorExceptionShare;

// Per axis, each coordinate's image and the folded place of that image.
struct FoldTables {
  std::array<std::vector<int>, 3> image, folded;
  FoldTables(const Dims3& d, const LebMirrorPlanes& planes) {
    for (int a = 0; a < 3; ++a) {
      const auto n = static_cast<std::size_t>(d[a]);
      image[a].resize(n);
      folded[a].resize(n);
      for (int c = 0; c < d[a]; ++c) {
        image[a][c] = lebMirrorImage(c, planes.sum[a]);
        folded[a][c] = lebFoldedCoordinate(c, planes.sum[a]);
      }
    }
  }
};

std::size_t linear(const Dims3& d, int x, int y, int z) {
  return static_cast<std::size_t>(x) +
         static_cast<std::size_t>(d[0]) * (static_cast<std::size_t>(y) + static_cast<std::size_t>(d[1]) * z);
}

// Walks every point of the volume in order with its image: f(index, x, y, z, imageIndex).
template <class F>
void forEachPointAndImage(const Dims3& d, const FoldTables& t, F&& f) {
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x)
        f(linear(d, x, y, z), x, y, z, linear(d, t.image[0][x], t.image[1][y], t.image[2][z]));
}

// Mirrored points that differ from their image under `planes`.
template <class T>
std::uint64_t differingPoints(const T* v, const Dims3& d, const LebMirrorPlanes& planes) {
  const FoldTables t(d, planes);
  std::uint64_t n = 0;
  forEachPointAndImage(d, t, [&](std::size_t i, int, int, int, std::size_t image) { n += v[i] != v[image]; });
  return n;
}

template <class T>
LebMirrorPlanes findPlanes(const T* v, const Dims3& d) {
  // The sample sums of the slices across each axis, in one pass.
  std::array<std::vector<double>, 3> slice;
  for (int a = 0; a < 3; ++a) slice[a].assign(static_cast<std::size_t>(d[a]), 0.0);
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) {
        const double s = v[linear(d, x, y, z)];
        slice[0][x] += s;
        slice[1][y] += s;
        slice[2][z] += s;
      }
  LebMirrorPlanes found;
  std::array<std::uint64_t, 3> differing{};
  for (int a = 0; a < 3; ++a) {
    const int n = d[a];
    if (n < 4) continue;
    double bestScore = 0;
    std::int64_t best = kNoLebMirror;
    int bestMirrored = 0;
    for (std::int64_t s = 1; s <= 2 * std::int64_t{n} - 3; ++s) {
      const int mirrored = static_cast<int>(std::min<std::int64_t>(s, n - 1) - s / 2);
      if (4 * mirrored < n) continue;
      double diff = 0, total = 1;
      for (int c = static_cast<int>(s / 2) + 1; c <= std::min<std::int64_t>(s, n - 1); ++c) {
        diff += std::abs(slice[a][c] - slice[a][s - c]);
        total += slice[a][c] + slice[a][s - c];
      }
      const double score = diff / total;
      if (best == kNoLebMirror || score < bestScore || (score == bestScore && mirrored > bestMirrored)) {
        best = s;
        bestScore = score;
        bestMirrored = mirrored;
      }
    }
    if (best == kNoLebMirror) continue;
    LebMirrorPlanes one;
    one.sum[a] = best;
    const std::uint64_t differ = differingPoints(v, d, one);
    if (differ * kSearchShare <= lebMirroredPoints(d, one)) {
      found.sum[a] = best;
      differing[a] = differ;
    }
  }
  // Together the planes may differ more than each alone: drop the worst until they fit.
  while (found.any() && differingPoints(v, d, found) * kSearchShare > lebMirroredPoints(d, found)) {
    int worst = -1;
    for (int a = 0; a < 3; ++a)
      if (found.sum[a] != kNoLebMirror && (worst < 0 || differing[a] > differing[worst])) worst = a;
    found.sum[worst] = kNoLebMirror;
  }
  return found;
}

template <class T>
std::vector<LebMirrorException> fold(const T* v, const Dims3& d, const LebMirrorPlanes& planes, int sampleBits,
                                     T* folded) {
  requireLebMirrorPlanes(d, planes);
  const FoldTables t(d, planes);
  std::vector<LebMirrorException> exceptions;
  std::size_t out = 0;
  forEachPointAndImage(d, t, [&](std::size_t i, int, int, int, std::size_t image) {
    if (image == i)
      folded[out++] = v[i];  // kept points come in the folded volume's order
    else if (v[i] != v[image])
      exceptions.push_back({i, lebMirrorResidual(v[i], v[image], sampleBits)});
  });
  const std::uint64_t cap = lebMirroredPoints(d, planes) / kLebMirrorExceptionShare;
  if (exceptions.size() > cap)
    throw std::invalid_argument("the mirror planes leave " + std::to_string(exceptions.size()) +
                                " points that differ from their image, more than the " + std::to_string(cap) +
                                " (one in " + std::to_string(kLebMirrorExceptionShare) +
                                " mirrored points) a mirrored stream may hold");
  return exceptions;
}

template <class T>
void unfold(T* v, const Dims3& d, const LebMirrorPlanes& planes, int sampleBits,
            const std::vector<LebMirrorException>& exceptions, const LebWindow& window) {
  requireLebMirrorPlanes(d, planes);
  const FoldTables t(d, planes);
  const Dims3 f = lebFoldedDims(d, planes);
  // From the last point back: a point's folded place is never after its own (mirror_fold.h).
  for (int z = d[2] - 1; z >= 0; --z) {
    for (int y = d[1] - 1; y >= 0; --y)
      for (int x = d[0] - 1; x >= 0; --x)
        v[linear(d, x, y, z)] = v[linear(f, t.folded[0][x], t.folded[1][y], t.folded[2][z])];
    if (window) window(static_cast<double>(d[2] - z) / d[2]);
  }
  for (const LebMirrorException& e : exceptions)
    v[e.index] = static_cast<T>(lebMirrorSample(v[e.index], e.residual, sampleBits));
}

}  // namespace

int lebFoldedExtent(int n, std::int64_t s) {
  if (s == kNoLebMirror) return n;
  return static_cast<int>(s / 2 + 1 + std::max<std::int64_t>(0, n - 1 - s));
}

int lebFoldedCoordinate(int c, std::int64_t s) {
  if (s == kNoLebMirror || 2 * std::int64_t{c} <= s) return c;
  if (c > s) return static_cast<int>(c - s + s / 2);  // after the kept [0, floor(s/2)]
  return static_cast<int>(s - c);                     // mirrored: its image, which is kept
}

Dims3 lebFoldedDims(const Dims3& d, const LebMirrorPlanes& planes) {
  return {lebFoldedExtent(d[0], planes.sum[0]), lebFoldedExtent(d[1], planes.sum[1]),
          lebFoldedExtent(d[2], planes.sum[2])};
}

std::uint64_t lebMirroredPoints(const Dims3& d, const LebMirrorPlanes& planes) {
  return sampleCount(d) - sampleCount(lebFoldedDims(d, planes));
}

std::string lebMirrorPlanesText(const LebMirrorPlanes& planes) {
  std::string t;
  for (int a = 0; a < 3; ++a)
    if (planes.sum[a] != kNoLebMirror)
      t += std::string(t.empty() ? "" : "; ") + kAxisName[a] + ": c <-> " + std::to_string(planes.sum[a]) + " - c";
  return t.empty() ? "none" : t;
}

void requireLebMirrorPlanes(const Dims3& d, const LebMirrorPlanes& planes) {
  for (int a = 0; a < 3; ++a)
    if (planes.sum[a] != kNoLebMirror && !lebMirrorSumValid(planes.sum[a], d[a]))
      throw std::invalid_argument(std::string("mirror sum on ") + kAxisName[a] + ": expected 1.." +
                                  std::to_string(2 * std::int64_t{d[a]} - 3) + " for an extent of " +
                                  std::to_string(d[a]) + ", got " + std::to_string(planes.sum[a]));
}

LebMirrorPlanes findLebMirrorPlanes(const std::uint8_t* samples, const Dims3& dims) {
  return findPlanes(samples, dims);
}
LebMirrorPlanes findLebMirrorPlanes(const std::uint16_t* samples, const Dims3& dims) {
  return findPlanes(samples, dims);
}

std::vector<LebMirrorException> foldLebVolume(const std::uint8_t* samples, const Dims3& dims,
                                              const LebMirrorPlanes& planes, std::uint8_t* folded) {
  return fold(samples, dims, planes, 8, folded);
}
std::vector<LebMirrorException> foldLebVolume(const std::uint16_t* samples, const Dims3& dims,
                                              const LebMirrorPlanes& planes, int sampleBits, std::uint16_t* folded) {
  return fold(samples, dims, planes, sampleBits, folded);
}

void unfoldLebVolume(std::uint8_t* samples, const Dims3& dims, const LebMirrorPlanes& planes,
                     const std::vector<LebMirrorException>& exceptions, const LebWindow& window) {
  unfold(samples, dims, planes, 8, exceptions, window);
}
void unfoldLebVolume(std::uint16_t* samples, const Dims3& dims, const LebMirrorPlanes& planes, int sampleBits,
                     const std::vector<LebMirrorException>& exceptions, const LebWindow& window) {
  unfold(samples, dims, planes, sampleBits, exceptions, window);
}

}  // namespace voxref::ref
