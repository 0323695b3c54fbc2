// Bitwise equality of two vectors of trivially copyable values.
#pragma once

#include <cstring>
#include <type_traits>
#include <vector>

namespace voxref::ref {

// The same length and the same bytes: floats are compared as bits, so -0 and +0 differ and a NaN
// equals itself. memcmp is not called on an empty vector, whose data() may be null.
template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  static_assert(std::is_trivially_copyable_v<T>);
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace voxref::ref
