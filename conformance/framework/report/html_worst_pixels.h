// The magnified view of a case's worst pixels (CaseResult::worstPixels) on its page: per pixel,
// a crop of 11 x 11 pixels around it from every image the case wrote, enlarged 8 times with
// `image-rendering: pixelated` (the pixel itself outlined), and its GL, emulated and reference
// values with their differences and, when an envelope judged it, the allowed interval and
// whether the GL value lies in it.
//
// Pixels are in GL order (row 0 at the bottom) while the PNG previews have row 0 at the top
// (case_images.h): the crop anchors the image by its bottom edge, so no image size is needed.
// Image paths are relative to the report directory; `toRoot` is the prefix from the page to it
// ("../" for cases/<id>.html).
#pragma once

#include <string>

#include "conformance/framework/case.h"

namespace voxref::conf {

// An <section id="worst-pixels">: the table (rows class="worst-pixel" with data-x, data-y, data-k)
// or a sentence saying the case singled out no pixel.
std::string worstPixelsSection(const CaseResult& r, const std::string& toRoot);

}  // namespace voxref::conf
