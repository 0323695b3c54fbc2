// The gradients the LEB codec stores beside the data (Gregorski et al. 2004, sections 2 and 3.1:
// "the normalized gradient vector at each data point ... quantized in three bytes with one byte
// per component").
//
// g = central differences of the samples (x fastest), one-sided on the volume's faces (and 0
// along an axis of extent 1), divided by the sample spacing. Each component of g / |g| is stored
// as snorm8, round(127 c) (GL 4.6 section 2.3.5.1, the inverse of snorm8 to float); a zero
// gradient is stored as (0, 0, 0). Computed in double; the rounding is std::lround (half away
// from zero). The paper smooths the float gradients by diffusion first; voxref does not.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "reference/common/volume.h"

namespace voxref::ref {

// Three int8 per sample, (gx, gy, gz), in the order of the volume's samples.
std::vector<std::int8_t> quantizedGradients(const Volume<std::uint16_t>& volume);

// The same bytes for samples of extents d at `samples` (8 or 16 bits, x fastest) into `out` (3 a
// sample): quantizedGradientSlice for every slice, slices in parallel on up to `threads` threads
// (parallel.h; 0: all cores), in batches of a few slices a worker; after each batch, on the calling
// thread while no worker runs, afterBatch(the fraction of the slices done), if set (a caller whose
// samples or output lie in file mappings trims them there). The same bytes for any thread count.
void quantizedGradientsInto(const std::uint8_t* samples, const Dims3& d, std::int8_t* out, int threads,
                            const std::function<void(double done)>& afterBatch = {});
void quantizedGradientsInto(const std::uint16_t* samples, const Dims3& d, std::int8_t* out, int threads,
                            const std::function<void(double done)>& afterBatch = {});

// The central-difference gradient of the sample at (x, y, z) (one-sided on the faces, 0 along an
// axis of extent 1), in sample units per sample spacing, of a volume of extents d whose sample at
// (qx, qy, qz) is sampleAt(qx, qy, qz) (it asks only for the six axis neighbours inside the volume,
// or (x, y, z) itself on a face). Random access into a stream that derives its gradients calls it
// with its own reconstruction (leb_reader.cpp); centralGradient with an array.
template <class SampleAt>
std::array<double, 3> centralGradientAt(SampleAt&& sampleAt, const Dims3& d, int x, int y, int z) {
  const int p[3] = {x, y, z};
  std::array<double, 3> g{0, 0, 0};
  for (int a = 0; a < 3; ++a) {
    if (d[a] < 2) continue;
    int lo[3] = {x, y, z}, hi[3] = {x, y, z};
    lo[a] = p[a] > 0 ? p[a] - 1 : p[a];
    hi[a] = p[a] + 1 < d[a] ? p[a] + 1 : p[a];
    g[static_cast<std::size_t>(a)] =
        (static_cast<double>(sampleAt(hi[0], hi[1], hi[2])) - static_cast<double>(sampleAt(lo[0], lo[1], lo[2]))) /
        (hi[a] - lo[a]);
  }
  return g;
}

// centralGradientAt of samples of extents d at `samples` (x fastest).
template <class T>
std::array<double, 3> centralGradient(const T* samples, const Dims3& d, int x, int y, int z) {
  return centralGradientAt(
      [&](int qx, int qy, int qz) {
        return samples[static_cast<std::size_t>(qx) +
                       static_cast<std::size_t>(d[0]) *
                           (static_cast<std::size_t>(qy) +
                            static_cast<std::size_t>(d[1]) * static_cast<std::size_t>(qz))];
      },
      d, x, y, z);
}

// g / |g| as snorm8, round(127 c) per component, into out[0..2]; (0, 0, 0) for a zero gradient.
inline void quantizeGradient(const std::array<double, 3>& g, std::int8_t* out) {
  const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  for (std::size_t a = 0; a < 3; ++a)
    out[a] = len == 0.0 ? 0 : static_cast<std::int8_t>(std::lround(127.0 * g[a] / len));
}

// std::lround of x for |x| <= 127 (half away from zero), without the library call: the truncation
// t is exact, and so is x - t.
inline std::int8_t roundHalfAwayFromZero(double x) {
  const int t = static_cast<int>(x);
  const double f = x - t;
  return static_cast<std::int8_t>(t + (f >= 0.5 ? 1 : 0) - (f <= -0.5 ? 1 : 0));
}

// quantizeGradient(centralGradient(...)) of a sample whose six axis neighbours lie in the volume,
// from the central differences e = (x+1) - (x-1) (integers, |e| < 2^16), to the same bits: there
// g = e / 2 exactly, |g| = sqrt(S / 4) = sqrt(S) / 2 for the integer S = e . e (the squares and
// their sum are exact in double, and a correctly rounded square root commutes with the exact
// scaling by 1/4; IEEE 754-2019 section 5.4.1), and (127 g) / |g| = (127 e / 2) / (sqrt(S) / 2)
// rounds as (127 e) / sqrt(S) (both operands scaled exactly by 1/2). |127 e / sqrt(S)| <= 127, so
// roundHalfAwayFromZero applies.
inline void interiorQuantizedGradient(std::int32_t ex, std::int32_t ey, std::int32_t ez, std::int8_t* out) {
  const std::int64_t s = std::int64_t{ex} * ex + std::int64_t{ey} * ey + std::int64_t{ez} * ez;
  if (s == 0) {
    out[0] = out[1] = out[2] = 0;
    return;
  }
  const double len = std::sqrt(static_cast<double>(s));
  out[0] = roundHalfAwayFromZero(127.0 * ex / len);
  out[1] = roundHalfAwayFromZero(127.0 * ey / len);
  out[2] = roundHalfAwayFromZero(127.0 * ez / len);
}

// The same for slice z alone (3 int8 per sample of the slice into out, x fastest), of samples of
// extents d at `samples` (x fastest): it reads slices z - 1 .. z + 1 only, so a file's gradients
// are made slice by slice (quantizedGradients is this for every z).
//
// The samples with both neighbours inside the volume on every axis take a shorter road to the same
// bits (interiorQuantizedGradient); the others, on the faces, take centralGradient.
template <class T>
void quantizedGradientSlice(const T* samples, const Dims3& d, int z, std::int8_t* out) {
  const bool interiorSlice = d[0] >= 3 && d[1] >= 3 && z > 0 && z + 1 < d[2];
  const auto sy = static_cast<std::ptrdiff_t>(d[0]), sz = sy * d[1];
  std::size_t i = 0;
  for (int y = 0; y < d[1]; ++y) {
    if (!interiorSlice || y == 0 || y + 1 == d[1]) {
      for (int x = 0; x < d[0]; ++x, ++i) quantizeGradient(centralGradient(samples, d, x, y, z), out + 3 * i);
      continue;
    }
    const T* row = samples + static_cast<std::ptrdiff_t>(z) * sz + static_cast<std::ptrdiff_t>(y) * sy;
    quantizeGradient(centralGradient(samples, d, 0, y, z), out + 3 * i++);
    for (int x = 1; x + 1 < d[0]; ++x, ++i) {
      const T* c = row + x;
      interiorQuantizedGradient(static_cast<std::int32_t>(c[1]) - c[-1], static_cast<std::int32_t>(c[sy]) - c[-sy],
                                static_cast<std::int32_t>(c[sz]) - c[-sz], out + 3 * i);
    }
    quantizeGradient(centralGradient(samples, d, d[0] - 1, y, z), out + 3 * i++);
  }
}

// The paper's Table 1 conditions (section 4: "the raw floating point gradients are run through a
// diffusion based smoothing process to ensure that there are no degenerate gradients"): the
// central-difference gradients, then `iterations` steps of explicit diffusion of each component,
// g <- g + (1/6) sum over the 6 axis neighbours of (g_n - g), a neighbour past a face counting as
// g itself (no flux through the faces; 1/6 is the largest stable step in 3D), then quantized as
// above. The paper gives neither the scheme nor its length; voxref's choice is this one, stated
// wherever its figures appear. Computed in double, in a fixed order: deterministic.
std::vector<std::int8_t> diffusedQuantizedGradients(const Volume<std::uint16_t>& volume, int iterations);

}  // namespace voxref::ref
