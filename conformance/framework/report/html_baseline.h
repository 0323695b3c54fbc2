// The index's comparison with an earlier run (`voxref conform --baseline`), drawn from
// RunInfo::baseline (baselineJson(), baseline_diff.h): whether anything regressed, the cases
// newly failing or warning, fixed, otherwise changed, and those whose figures moved (before ->
// after), each linked to its page; the counts of cases added and missing. Robust to a document
// lacking any of these keys. Every text is escaped.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace voxref::conf {

// <section id="baseline">, or "" when `baseline` is not an object (no --baseline).
std::string baselineSection(const nlohmann::json& baseline);

}  // namespace voxref::conf
