#include "conformance/framework/report/worst_samples.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace voxref::conf {

std::vector<std::size_t> largestScores(const std::vector<double>& scores, std::size_t n) {
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < scores.size(); ++i)
    if (scores[i] > 0.0) idx.push_back(i);  // false for NaN
  const auto worse = [&](std::size_t a, std::size_t b) {
    return scores[a] != scores[b] ? scores[a] > scores[b] : a < b;
  };
  const std::size_t keep = std::min(n, idx.size());
  std::partial_sort(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(keep), idx.end(), worse);
  idx.resize(keep);
  return idx;
}

std::vector<std::size_t> interleaveRanked(const std::vector<std::vector<std::size_t>>& lists, std::size_t n) {
  std::vector<std::size_t> out;
  std::unordered_set<std::size_t> taken;
  for (std::size_t rank = 0; out.size() < n; ++rank) {
    bool any = false;
    for (const std::vector<std::size_t>& list : lists) {
      if (rank >= list.size()) continue;
      any = true;
      if (out.size() < n && taken.insert(list[rank]).second) out.push_back(list[rank]);
    }
    if (!any) break;
  }
  return out;
}

}  // namespace voxref::conf
