#include "conformance/framework/report/case_images.h"

#include <algorithm>
#include <cmath>

namespace voxref::conf {
namespace {

std::uint8_t toByte(double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

}  // namespace

io::Rgb8Image grayPreview(const ref::Image& image, double scale) {
  io::Rgb8Image out{image.width, image.height,
                    std::vector<std::uint8_t>(static_cast<std::size_t>(image.width) * image.height * 3)};
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const std::uint8_t g =
          toByte(image.pixels[static_cast<std::size_t>(i) + static_cast<std::size_t>(image.width) * j] * scale);
      std::uint8_t* px =
          &out.rgb[3 * (static_cast<std::size_t>(i) + static_cast<std::size_t>(image.width) * (image.height - 1 - j))];
      px[0] = px[1] = px[2] = g;
    }
  return out;
}

io::Rgb8Image errorMaskPreview(const ref::Image& base, double scale, const std::vector<PixelFlag>& flags) {
  io::Rgb8Image out = grayPreview(base, scale * 0.35);
  for (int j = 0; j < base.height; ++j)
    for (int i = 0; i < base.width; ++i) {
      const PixelFlag f = flags[static_cast<std::size_t>(i) + static_cast<std::size_t>(base.width) * j];
      std::uint8_t* px =
          &out.rgb[3 * (static_cast<std::size_t>(i) + static_cast<std::size_t>(base.width) * (base.height - 1 - j))];
      switch (f) {
        case PixelFlag::ExactMismatch:
          px[0] = 255, px[1] = 0, px[2] = 0;
          break;
        case PixelFlag::EnvelopeFail:
          px[0] = 255, px[1] = 0, px[2] = 255;
          break;
        case PixelFlag::EnvelopeWarn:
          px[0] = 255, px[1] = 220, px[2] = 0;
          break;
        case PixelFlag::None:
          break;
      }
    }
  return out;
}

std::string caseImageName(const std::string& caseId, const std::string& kind) {
  return "images/" + caseId + "." + kind + ".png";
}

}  // namespace voxref::conf
