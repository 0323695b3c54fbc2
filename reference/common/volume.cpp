#include "reference/common/volume.h"

namespace voxref::ref {

std::size_t sampleCount(const Dims3& dims, std::size_t limit) {
  std::size_t n = 1;
  for (int d : dims) {
    if (d <= 0) throw std::invalid_argument("volume extent " + std::to_string(d) + " is not positive");
    if (n > limit / static_cast<std::size_t>(d))
      throw std::invalid_argument("volume of " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                                  std::to_string(dims[2]) + " samples exceeds the limit of " + std::to_string(limit));
    n *= static_cast<std::size_t>(d);
  }
  return n;
}

}  // namespace voxref::ref
