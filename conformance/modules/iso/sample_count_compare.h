// Two counts of the same occlusion tests by GL's two counters (gpu/iso_gl.h, SampleCounter): the
// GL and GLSL specifications make them equal box for box (gpu/shaders/occlusion_count.frag), so
// any difference is a driver's (or voxref's) departure from them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace voxref::conf {

struct SampleCountComparison {
  std::size_t boxes = 0;              // compared
  std::size_t differing = 0;          // boxes whose counts differ
  std::size_t verdictsDiffering = 0;  // of those, boxes one counter finds hidden (0) and the other not
  std::string first;                  // the first difference, described; empty when none
};

// Compares `byQueries` with `inBuffer`, box for box. Throws std::invalid_argument when their sizes
// differ (they must count the same boxes).
SampleCountComparison compareSampleCounts(std::span<const std::uint32_t> byQueries,
                                          std::span<const std::uint32_t> inBuffer);

// `total` with `more` added to it (first difference kept from `total` when it has one).
void accumulate(SampleCountComparison& total, const SampleCountComparison& more);

}  // namespace voxref::conf
