#include "reference/common/crc32.h"

#include <array>

namespace voxref::ref {
namespace {

// The byte-wise table of the reflected polynomial 0xEDB88320 (Sarwate's algorithm).
constexpr std::array<std::uint32_t, 256> makeTable() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int b = 0; b < 8; ++b) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[i] = c;
  }
  return t;
}
constexpr std::array<std::uint32_t, 256> kTable = makeTable();

}  // namespace

std::uint32_t crc32Update(std::uint32_t crc, std::string_view bytes) {
  std::uint32_t c = ~crc;
  for (const char ch : bytes) c = kTable[(c ^ static_cast<unsigned char>(ch)) & 0xffu] ^ (c >> 8);
  return ~c;
}

}  // namespace voxref::ref
