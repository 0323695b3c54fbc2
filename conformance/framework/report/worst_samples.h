// Choosing the samples a case singles out for the report's magnified view
// (CaseResult::worstPixels): pure functions over per-sample scores, deterministic (ties go to the
// lower index), so the same run always shows the same pixels.
#pragma once

#include <cstddef>
#include <vector>

namespace voxref::conf {

// The indices of the (at most) n largest scores, largest first, ties by lower index. Scores that
// are NaN or <= 0 mean "nothing wrong here" and are never chosen.
std::vector<std::size_t> largestScores(const std::vector<double>& scores, std::size_t n);

// Merges ranked lists round robin (the first of each list, then the second of each ...),
// skipping indices already taken, until n are taken or the lists run out: every kind of
// failure gets its worst samples shown.
std::vector<std::size_t> interleaveRanked(const std::vector<std::vector<std::size_t>>& lists, std::size_t n);

}  // namespace voxref::conf
