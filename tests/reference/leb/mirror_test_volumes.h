// Test helper: volumes and gradients made mirror images of themselves by the definition of a fold
// (reference/leb/mirror_fold.h), written out here with integers rather than through the fold's
// own functions, shared by the fold and the mirrored stream tests.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/common/volume.h"
#include "reference/leb/mirror_fold.h"

namespace voxref::ref::test_support {

// c's image under sum s: s - c when s/2 < c <= s, else c itself.
inline int mirrorImageOf(int c, std::int64_t s) {
  return s >= 0 && 2 * std::int64_t{c} > s && c <= s ? static_cast<int>(s - c) : c;
}

// `v` made a mirror image of itself: each point whose coordinates are mirrored takes its image's
// sample, so the planes hold exactly.
inline Volume<std::uint16_t> mirrored(Volume<std::uint16_t> v, const LebMirrorPlanes& planes) {
  const Dims3 d = v.dims();
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x)
        v.at(x, y, z) =
            v.at(mirrorImageOf(x, planes.sum[0]), mirrorImageOf(y, planes.sum[1]), mirrorImageOf(z, planes.sum[2]));
  return v;
}

// A gradient component negated in 8 bits (two's complement wraps -(-128) to -128).
inline std::int8_t negatedComponent(std::int8_t c) { return static_cast<std::int8_t>(c == -128 ? -128 : -c); }

// Gradients `g` (3 int8 a point of extents d) made to mirror exactly: each mirrored point takes its
// image's, with the component of each axis on which the point is mirrored negated.
inline std::vector<std::int8_t> mirroredGradients(std::vector<std::int8_t> g, const Dims3& d,
                                                  const LebMirrorPlanes& planes) {
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) {
        const int p[3] = {x, y, z};
        int q[3];
        for (int a = 0; a < 3; ++a) q[a] = mirrorImageOf(p[a], planes.sum[a]);
        const std::size_t i = 3 * (static_cast<std::size_t>(x) + static_cast<std::size_t>(d[0]) * (y + d[1] * z));
        const std::size_t j =
            3 * (static_cast<std::size_t>(q[0]) + static_cast<std::size_t>(d[0]) * (q[1] + d[1] * q[2]));
        for (int a = 0; a < 3; ++a) g[i + a] = q[a] != p[a] ? negatedComponent(g[j + a]) : g[j + a];
      }
  return g;
}

}  // namespace voxref::ref::test_support
