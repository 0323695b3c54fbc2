#include "conformance/modules/iso/sample_count_compare.h"

#include <stdexcept>

namespace voxref::conf {

SampleCountComparison compareSampleCounts(std::span<const std::uint32_t> byQueries,
                                          std::span<const std::uint32_t> inBuffer) {
  if (byQueries.size() != inBuffer.size())
    throw std::invalid_argument("sample counts: " + std::to_string(byQueries.size()) + " boxes by queries, " +
                                std::to_string(inBuffer.size()) + " in the buffer");
  SampleCountComparison c;
  c.boxes = byQueries.size();
  for (std::size_t i = 0; i < byQueries.size(); ++i) {
    if (byQueries[i] == inBuffer[i]) continue;
    ++c.differing;
    if ((byQueries[i] == 0) != (inBuffer[i] == 0)) ++c.verdictsDiffering;
    if (c.first.empty())
      c.first = "box " + std::to_string(i) + ": " + std::to_string(byQueries[i]) + " samples by its query, " +
                std::to_string(inBuffer[i]) + " in the buffer";
  }
  return c;
}

void accumulate(SampleCountComparison& total, const SampleCountComparison& more) {
  total.boxes += more.boxes;
  total.differing += more.differing;
  total.verdictsDiffering += more.verdictsDiffering;
  if (total.first.empty()) total.first = more.first;
}

}  // namespace voxref::conf
