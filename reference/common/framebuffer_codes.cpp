#include "reference/common/framebuffer_codes.h"

#include <bit>

#include "reference/common/rounding.h"

namespace voxref::ref {

double decodeFramebufferCode(FramebufferFormat format, std::uint32_t code) {
  switch (format) {
    case FramebufferFormat::RGBA8:
    case FramebufferFormat::RGBA12:
    case FramebufferFormat::RGBA16:
      return unormToDouble(code, unormBits(format));
    case FramebufferFormat::RGBA16F:
      return halfToDouble(static_cast<std::uint16_t>(code));
    case FramebufferFormat::RGBA32F:
      return std::bit_cast<float>(code);
  }
  return 0.0;
}

SampleStack toSampleStack(const CodePlanes& p, double scale) {
  SampleStack s{p.width, p.height, p.planes, std::vector<double>(p.codes.size())};
  for (std::size_t i = 0; i < p.codes.size(); ++i) s.values[i] = scale * decodeFramebufferCode(p.format, p.codes[i]);
  return s;
}

}  // namespace voxref::ref
