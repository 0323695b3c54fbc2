// Previews of a case for the HTML report: shaded images as 8-bit PNG (all three on the scale of
// the reference image) and an error mask that shows which pixels an oracle flagged.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "conformance/io/image_io.h"
#include "reference/common/plane_shading.h"

namespace voxref::conf {

// Row 0 of `image` is at the bottom (GL); the PNG row 0 at the top.
io::Rgb8Image grayPreview(const ref::Image& image, double scale);

enum class PixelFlag : std::uint8_t { None = 0, EnvelopeWarn = 1, EnvelopeFail = 2, ExactMismatch = 3 };
// `flags` per pixel (width * height, GL row order): red exact mismatch, magenta envelope
// failure, yellow envelope warning; other pixels show `base` dimmed.
io::Rgb8Image errorMaskPreview(const ref::Image& base, double scale, const std::vector<PixelFlag>& flags);

// The file name for an image of a case in the report's images/ folder.
std::string caseImageName(const std::string& caseId, const std::string& kind);

}  // namespace voxref::conf
