// A dense 3D array of samples, x fastest (offset = x + X * (y + Y * z)), as in raw volume files
// (conformance/io/raw_volume.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace voxref::ref {

using Dims3 = std::array<int, 3>;

// Number of samples of `dims`; throws std::invalid_argument for a non-positive extent or a
// count above `limit` (checked before any multiplication can overflow).
std::size_t sampleCount(const Dims3& dims, std::size_t limit = std::size_t{1} << 40);
// "XxYxZ", for messages and tables that name a volume's extents.
inline std::string dimsText(const Dims3& d) {
  return std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]);
}

template <class T>
class Volume {
 public:
  Volume() = default;
  explicit Volume(const Dims3& dims, T fill = T{}) : dims_(dims), data_(sampleCount(dims), fill) {}
  Volume(const Dims3& dims, std::vector<T> data) : dims_(dims), data_(std::move(data)) {
    if (data_.size() != sampleCount(dims))
      throw std::invalid_argument("volume data has " + std::to_string(data_.size()) + " samples, dimensions need " +
                                  std::to_string(sampleCount(dims)));
  }

  const Dims3& dims() const { return dims_; }
  std::size_t index(int x, int y, int z) const {
    return static_cast<std::size_t>(x) +
           static_cast<std::size_t>(dims_[0]) * (static_cast<std::size_t>(y) + static_cast<std::size_t>(dims_[1]) * z);
  }
  T& at(int x, int y, int z) { return data_[index(x, y, z)]; }
  const T& at(int x, int y, int z) const { return data_[index(x, y, z)]; }
  std::vector<T>& data() { return data_; }
  const std::vector<T>& data() const { return data_; }

 private:
  Dims3 dims_{0, 0, 0};
  std::vector<T> data_;
};

// The samples of an 8-bit volume as 16-bit ones (the codecs and the isosurface system work on
// uint16).
inline Volume<std::uint16_t> widenToU16(const Volume<std::uint8_t>& v) {
  return Volume<std::uint16_t>(v.dims(), std::vector<std::uint16_t>(v.data().begin(), v.data().end()));
}

}  // namespace voxref::ref
