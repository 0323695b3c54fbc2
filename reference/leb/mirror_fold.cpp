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
// ... and at most one differing in its sample or gradient in this many, when gradients are folded.
constexpr std::uint64_t kGradientSearchShare = 2 * kLebMirrorGradientExceptionShare;

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

// Whether a point with coordinates (x, y, z) is mirrored on each axis (its gradient's component
// there is negated in its image's).
std::array<bool, 3> flips(const FoldTables& t, int x, int y, int z) {
  return {t.image[0][x] != x, t.image[1][y] != y, t.image[2][z] != z};
}

// Point i against its image: the residual of its sample, and of its gradient when `g` is given.
template <class T>
LebMirrorException residualOf(const T* v, const std::int8_t* g, int sampleBits, std::size_t i, std::size_t image,
                              const std::array<bool, 3>& flipped) {
  LebMirrorException e{i, lebMirrorResidual(v[i], v[image], sampleBits), {}};
  if (g)
    for (int c = 0; c < 3; ++c) e.gradient[c] = lebMirrorComponentResidual(g[3 * i + c], g[3 * image + c], flipped[c]);
  return e;
}
bool differs(const LebMirrorException& e) { return e.residual != 0 || e.gradient != std::array<std::uint8_t, 3>{}; }

// Mirrored points that differ from their image under `planes`: in their sample, and in their
// sample or their gradient (the same count without gradients).
struct Differing {
  std::uint64_t samples = 0, any = 0;
};
template <class T>
Differing differingPoints(const T* v, const std::int8_t* g, const Dims3& d, const LebMirrorPlanes& planes) {
  const FoldTables t(d, planes);
  Differing n;
  forEachPointAndImage(d, t, [&](std::size_t i, int x, int y, int z, std::size_t image) {
    if (image == i) return;
    const LebMirrorException e = residualOf(v, g, 16, i, image, flips(t, x, y, z));
    n.samples += e.residual != 0;
    n.any += differs(e);
  });
  return n;
}

// Whether the differing points are few enough to fold (findLebMirrorPlanes' shares).
bool worthFolding(const Differing& n, const Dims3& d, const LebMirrorPlanes& planes) {
  const std::uint64_t mirrored = lebMirroredPoints(d, planes);
  return n.samples * kSearchShare <= mirrored && n.any * kGradientSearchShare <= mirrored;
}

template <class T>
LebMirrorPlanes findPlanes(const T* v, const std::int8_t* g, const Dims3& d) {
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
    const Differing differ = differingPoints(v, g, d, one);
    if (worthFolding(differ, d, one)) {
      found.sum[a] = best;
      differing[a] = differ.any;
    }
  }
  // Together the planes may differ more than each alone: drop the worst until they fit.
  while (found.any() && !worthFolding(differingPoints(v, g, d, found), d, found)) {
    int worst = -1;
    for (int a = 0; a < 3; ++a)
      if (found.sum[a] != kNoLebMirror && (worst < 0 || differing[a] > differing[worst])) worst = a;
    found.sum[worst] = kNoLebMirror;
  }
  return found;
}

template <class T>
std::vector<LebMirrorException> fold(const T* v, const std::int8_t* g, const Dims3& d, const LebMirrorPlanes& planes,
                                     int sampleBits, T* folded, std::int8_t* foldedGradients) {
  requireLebMirrorPlanes(d, planes);
  if (g && !foldedGradients) throw std::invalid_argument("foldLebVolume: gradients to fold but none to fold them into");
  const FoldTables t(d, planes);
  const std::uint64_t cap = lebMirrorExceptionCap(d, planes, g != nullptr);
  std::vector<LebMirrorException> exceptions;
  std::uint64_t differing = 0;  // past the cap they are counted, not kept
  std::size_t out = 0;
  forEachPointAndImage(d, t, [&](std::size_t i, int x, int y, int z, std::size_t image) {
    if (image == i) {  // kept points come in the folded volume's order
      if (g) std::copy_n(g + 3 * i, 3, foldedGradients + 3 * out);
      folded[out++] = v[i];
    } else if (const LebMirrorException e = residualOf(v, g, sampleBits, i, image, flips(t, x, y, z)); differs(e)) {
      if (++differing <= cap) exceptions.push_back(e);
    }
  });
  if (differing > cap)
    throw std::invalid_argument("the mirror planes leave " + std::to_string(differing) +
                                " points that differ from their image" + (g ? " in their sample or gradient" : "") +
                                ", more than the " + std::to_string(cap) + " (one in " +
                                std::to_string(g ? kLebMirrorGradientExceptionShare : kLebMirrorExceptionShare) +
                                " mirrored points) a mirrored stream may hold");
  return exceptions;
}

template <class T>
void unfold(T* v, std::int8_t* g, const Dims3& d, const LebMirrorPlanes& planes, int sampleBits,
            const std::vector<LebMirrorException>& exceptions, const LebWindow& window) {
  requireLebMirrorPlanes(d, planes);
  const FoldTables t(d, planes);
  const Dims3 f = lebFoldedDims(d, planes);
  // From the last point back: a point's folded place is never after its own (mirror_fold.h).
  for (int z = d[2] - 1; z >= 0; --z) {
    for (int y = d[1] - 1; y >= 0; --y)
      for (int x = d[0] - 1; x >= 0; --x) {
        const std::size_t i = linear(d, x, y, z), from = linear(f, t.folded[0][x], t.folded[1][y], t.folded[2][z]);
        v[i] = v[from];
        if (g) {
          const std::array<bool, 3> flipped = flips(t, x, y, z);
          for (int c = 0; c < 3; ++c) g[3 * i + c] = lebMirrorComponent(g[3 * from + c], flipped[c], 0);
        }
      }
    if (window) window(static_cast<double>(d[2] - z) / d[2]);
  }
  for (const LebMirrorException& e : exceptions) {
    v[e.index] = static_cast<T>(lebMirrorSample(v[e.index], e.residual, sampleBits));
    if (g)
      for (int c = 0; c < 3; ++c) g[3 * e.index + c] = lebMirrorComponent(g[3 * e.index + c], false, e.gradient[c]);
  }
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

std::uint64_t lebMirrorExceptionCap(const Dims3& d, const LebMirrorPlanes& planes, bool gradients) {
  return lebMirroredPoints(d, planes) / (gradients ? kLebMirrorGradientExceptionShare : kLebMirrorExceptionShare);
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

LebMirrorPlanes findLebMirrorPlanes(const std::uint8_t* samples, const std::int8_t* gradients, const Dims3& dims) {
  return findPlanes(samples, gradients, dims);
}
LebMirrorPlanes findLebMirrorPlanes(const std::uint16_t* samples, const std::int8_t* gradients, const Dims3& dims) {
  return findPlanes(samples, gradients, dims);
}

std::vector<LebMirrorException> foldLebVolume(const std::uint8_t* samples, const std::int8_t* gradients,
                                              const Dims3& dims, const LebMirrorPlanes& planes, std::uint8_t* folded,
                                              std::int8_t* foldedGradients) {
  return fold(samples, gradients, dims, planes, 8, folded, foldedGradients);
}
std::vector<LebMirrorException> foldLebVolume(const std::uint16_t* samples, const std::int8_t* gradients,
                                              const Dims3& dims, const LebMirrorPlanes& planes, int sampleBits,
                                              std::uint16_t* folded, std::int8_t* foldedGradients) {
  return fold(samples, gradients, dims, planes, sampleBits, folded, foldedGradients);
}

void unfoldLebVolume(std::uint8_t* samples, std::int8_t* gradients, const Dims3& dims, const LebMirrorPlanes& planes,
                     const std::vector<LebMirrorException>& exceptions, const LebWindow& window) {
  unfold(samples, gradients, dims, planes, 8, exceptions, window);
}
void unfoldLebVolume(std::uint16_t* samples, std::int8_t* gradients, const Dims3& dims, const LebMirrorPlanes& planes,
                     int sampleBits, const std::vector<LebMirrorException>& exceptions, const LebWindow& window) {
  unfold(samples, gradients, dims, planes, sampleBits, exceptions, window);
}

}  // namespace voxref::ref
