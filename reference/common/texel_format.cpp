#include "reference/common/texel_format.h"

#include <bit>

#include "reference/common/rounding.h"

namespace voxref::ref {

std::uint32_t encodeTexel(TexelFormat format, double value) {
  switch (format) {
    case TexelFormat::R8:
    case TexelFormat::RGBA8:
      return unormFromDouble(value, 8);
    case TexelFormat::R16:
      return unormFromDouble(value, 16);
    case TexelFormat::R16F:
      return halfFromDouble(value);
    case TexelFormat::R32F:
      return std::bit_cast<std::uint32_t>(static_cast<float>(value));
  }
  return 0;
}

double decodeTexel(TexelFormat format, std::uint32_t code) {
  switch (format) {
    case TexelFormat::R8:
    case TexelFormat::RGBA8:
      return unormToDouble(code, 8);
    case TexelFormat::R16:
      return unormToDouble(code, 16);
    case TexelFormat::R16F:
      return halfToDouble(static_cast<std::uint16_t>(code));
    case TexelFormat::R32F:
      return std::bit_cast<float>(code);
  }
  return 0.0;
}

int bytesPerTexel(TexelFormat format) {
  switch (format) {
    case TexelFormat::R8:
      return 1;
    case TexelFormat::RGBA8:
      return 4;
    case TexelFormat::R16:
    case TexelFormat::R16F:
      return 2;
    case TexelFormat::R32F:
      return 4;
  }
  return 0;
}

int unormBits(TexelFormat format) {
  switch (format) {
    case TexelFormat::R8:
    case TexelFormat::RGBA8:
      return 8;
    case TexelFormat::R16:
      return 16;
    case TexelFormat::R16F:
    case TexelFormat::R32F:
      return 0;
  }
  return 0;
}

}  // namespace voxref::ref
