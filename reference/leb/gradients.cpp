#include "reference/leb/gradients.h"

#include <cmath>

namespace voxref::ref {

std::vector<std::int8_t> quantizedGradients(const Volume<std::uint16_t>& v) {
  const Dims3& d = v.dims();
  std::vector<std::int8_t> out(3 * v.data().size(), 0);
  std::size_t i = 0;
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x, ++i) {
        const int p[3] = {x, y, z};
        double g[3] = {0, 0, 0};
        for (int a = 0; a < 3; ++a) {
          if (d[a] < 2) continue;
          int lo[3] = {x, y, z}, hi[3] = {x, y, z};
          lo[a] = p[a] > 0 ? p[a] - 1 : p[a];
          hi[a] = p[a] + 1 < d[a] ? p[a] + 1 : p[a];
          g[a] = (static_cast<double>(v.at(hi[0], hi[1], hi[2])) - static_cast<double>(v.at(lo[0], lo[1], lo[2]))) /
                 (hi[a] - lo[a]);
        }
        const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (len == 0.0) continue;
        for (int a = 0; a < 3; ++a)
          out[3 * i + static_cast<std::size_t>(a)] = static_cast<std::int8_t>(std::lround(127.0 * g[a] / len));
      }
  return out;
}

}  // namespace voxref::ref
