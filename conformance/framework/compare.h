// Pure comparison functions, one per kind of comparison (after Khronos tcuImageCompare.cpp):
// each takes what was produced and what was expected and returns its figures and, where useful,
// a per-sample mask for the report. No thresholds live here: callers state theirs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "reference/common/framebuffer_codes.h"
#include "reference/common/plane_shading.h"
#include "reference/common/rgba.h"

namespace voxref::conf {

// Distance between two stored codes of a format: |a - b| for unorm codes, the number of
// representable values between them for binary16 / binary32 (ULPs; +0 and -0 are one value).
std::uint64_t codeDistance(ref::FramebufferFormat format, std::uint32_t a, std::uint32_t b);

struct CodeComparison {
  std::size_t compared = 0;        // samples compared
  std::size_t excluded = 0;        // samples left out by `exclude` (reported, never hidden)
  std::size_t mismatched = 0;      // samples whose codes differ in any bit
  std::uint64_t maxDistance = 0;   // largest codeDistance (LSB or ULP)
  std::size_t firstMismatch = 0;   // index of the first differing sample (if any)
  std::vector<std::uint8_t> mask;  // 1 where the codes differ
};
// Bit-for-bit comparison of two read-backs of the same format and size (std::invalid_argument
// otherwise). `exclude` (optional, same size) marks samples not to judge.
CodeComparison compareCodes(const ref::CodePlanes& actual, const ref::CodePlanes& expected,
                            const std::vector<std::uint8_t>* exclude = nullptr);

struct ErrorFigures {
  std::size_t count = 0;
  double maxAbs = 0.0;
  std::size_t argMax = 0;
  double rmse = 0.0;
  double psnrDb = 0.0;  // 20 log10(peak / rmse); +infinity when rmse == 0
};
// Distance of values from reference values (same size), PSNR against `peak`.
ErrorFigures compareValues(const std::vector<double>& actual, const std::vector<double>& reference, double peak);

// Pixels of two images that differ at all, and the largest difference.
struct ImageComparison {
  std::size_t mismatchedPixels = 0;
  double maxAbs = 0.0;
};
ImageComparison compareImages(const ref::Image& a, const ref::Image& b);

// The largest difference between two RGBA8 colours over their channels (codes), and its channel
// (0..3, r g b a; the first of equal ones; 0 and difference 0 for equal colours).
struct ChannelDifference {
  int difference = 0;
  int channel = 0;
};
ChannelDifference largestChannelDifference(const ref::Rgba8& a, const ref::Rgba8& b);

}  // namespace voxref::conf
