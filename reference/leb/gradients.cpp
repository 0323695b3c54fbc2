#include "reference/leb/gradients.h"

#include <algorithm>

#include "reference/common/parallel.h"

namespace voxref::ref {

namespace {

template <class T>
void slicesInto(const T* samples, const Dims3& d, std::int8_t* out, int threads,
                const std::function<void(double)>& afterBatch) {
  const std::size_t slice = 3 * static_cast<std::size_t>(d[0]) * static_cast<std::size_t>(d[1]);
  const int batch = 4 * workerCount(threads);
  for (int z0 = 0; z0 < d[2]; z0 += batch) {
    const int z1 = std::min(d[2], z0 + batch);
    parallelFor(z1 - z0, threads, [&](int i) {
      quantizedGradientSlice(samples, d, z0 + i, out + slice * static_cast<std::size_t>(z0 + i));
    });
    if (afterBatch) afterBatch(static_cast<double>(z1) / d[2]);
  }
}

}  // namespace

void quantizedGradientsInto(const std::uint8_t* samples, const Dims3& d, std::int8_t* out, int threads,
                            const std::function<void(double)>& afterBatch) {
  slicesInto(samples, d, out, threads, afterBatch);
}

void quantizedGradientsInto(const std::uint16_t* samples, const Dims3& d, std::int8_t* out, int threads,
                            const std::function<void(double)>& afterBatch) {
  slicesInto(samples, d, out, threads, afterBatch);
}

std::vector<std::int8_t> quantizedGradients(const Volume<std::uint16_t>& v) {
  std::vector<std::int8_t> out(3 * v.data().size(), 0);
  quantizedGradientsInto(v.data().data(), v.dims(), out.data(), 1);
  return out;
}

std::vector<std::int8_t> diffusedQuantizedGradients(const Volume<std::uint16_t>& v, int iterations) {
  const Dims3& d = v.dims();
  const std::size_t n = v.data().size();
  std::vector<std::array<double, 3>> g(n), next(n);
  std::size_t i = 0;
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) g[i++] = centralGradient(v.data().data(), d, x, y, z);
  const std::ptrdiff_t stride[3] = {1, d[0], static_cast<std::ptrdiff_t>(d[0]) * d[1]};
  for (int it = 0; it < iterations; ++it) {
    i = 0;
    for (int z = 0; z < d[2]; ++z)
      for (int y = 0; y < d[1]; ++y)
        for (int x = 0; x < d[0]; ++x, ++i) {
          const int p[3] = {x, y, z};
          std::array<double, 3> flux{0, 0, 0};
          for (int a = 0; a < 3; ++a)
            for (const int step : {-1, 1}) {
              if (p[a] + step < 0 || p[a] + step >= d[a]) continue;  // the face: no flux
              const std::array<double, 3>& q =
                  g[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + step * stride[a])];
              for (std::size_t c = 0; c < 3; ++c) flux[c] += q[c] - g[i][c];
            }
          for (std::size_t c = 0; c < 3; ++c) next[i][c] = g[i][c] + flux[c] / 6.0;
        }
    g.swap(next);
  }
  std::vector<std::int8_t> out(3 * n);
  for (i = 0; i < n; ++i) quantizeGradient(g[i], out.data() + 3 * i);
  return out;
}

}  // namespace voxref::ref
