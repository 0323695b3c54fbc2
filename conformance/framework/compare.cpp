#include "conformance/framework/compare.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "reference/common/gl_state.h"

namespace voxref::conf {
namespace {

// Maps float bits onto a line of integers ordered like the values (sign-magnitude to offset).
std::int64_t orderedFloatBits(std::uint32_t bits, int width) {
  const std::uint32_t signBit = 1u << (width - 1);
  const std::int64_t magnitude = bits & (signBit - 1);
  return (bits & signBit) ? -magnitude : magnitude;
}

}  // namespace

std::uint64_t codeDistance(ref::FramebufferFormat format, std::uint32_t a, std::uint32_t b) {
  if (ref::unormBits(format)) return a > b ? a - b : b - a;
  const int width = format == ref::FramebufferFormat::RGBA16F ? 16 : 32;
  const std::int64_t d = orderedFloatBits(a, width) - orderedFloatBits(b, width);
  return static_cast<std::uint64_t>(d < 0 ? -d : d);
}

CodeComparison compareCodes(const ref::CodePlanes& actual, const ref::CodePlanes& expected,
                            const std::vector<std::uint8_t>* exclude) {
  if (actual.format != expected.format || actual.codes.size() != expected.codes.size() ||
      (exclude && exclude->size() != actual.codes.size()))
    throw std::invalid_argument("compareCodes: read-backs differ in format or size");
  CodeComparison c;
  c.mask.assign(actual.codes.size(), 0);
  for (std::size_t i = 0; i < actual.codes.size(); ++i) {
    if (exclude && (*exclude)[i]) {
      ++c.excluded;
      continue;
    }
    ++c.compared;
    if (actual.codes[i] == expected.codes[i]) continue;
    if (c.mismatched++ == 0) c.firstMismatch = i;
    c.mask[i] = 1;
    c.maxDistance = std::max(c.maxDistance, codeDistance(actual.format, actual.codes[i], expected.codes[i]));
  }
  return c;
}

ErrorFigures compareValues(const std::vector<double>& actual, const std::vector<double>& reference, double peak) {
  if (actual.size() != reference.size()) throw std::invalid_argument("compareValues: sizes differ");
  ErrorFigures f;
  f.count = actual.size();
  double sumSq = 0.0;
  for (std::size_t i = 0; i < actual.size(); ++i) {
    const double d = std::fabs(actual[i] - reference[i]);
    if (d > f.maxAbs) {
      f.maxAbs = d;
      f.argMax = i;
    }
    sumSq += d * d;
  }
  f.rmse = f.count ? std::sqrt(sumSq / static_cast<double>(f.count)) : 0.0;
  f.psnrDb = f.rmse > 0.0 ? 20.0 * std::log10(peak / f.rmse) : std::numeric_limits<double>::infinity();
  return f;
}

ImageComparison compareImages(const ref::Image& a, const ref::Image& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("compareImages: sizes differ");
  ImageComparison c;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = std::fabs(a.pixels[i] - b.pixels[i]);
    if (a.pixels[i] != b.pixels[i]) ++c.mismatchedPixels;
    c.maxAbs = std::max(c.maxAbs, d);
  }
  return c;
}

ChannelDifference largestChannelDifference(const ref::Rgba8& a, const ref::Rgba8& b) {
  ChannelDifference d;
  for (int c = 0; c < 4; ++c)
    if (std::abs(int(a[c]) - int(b[c])) > d.difference) d = {std::abs(int(a[c]) - int(b[c])), c};
  return d;
}

}  // namespace voxref::conf
