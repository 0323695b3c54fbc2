// What judged each system's cases (issue 16): per system, how many cases each oracle judged on GL
// (framework/case.h, Judge), how many nothing judged, and the outcomes. One count serves the
// terminal summary, results.json, junit.xml and index.html.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/framework/case.h"

namespace voxref::conf {

struct SystemJudgement {
  std::map<Judge, int> judgedBy;  // Judge::None: not judged
  std::map<Status, int> outcomes;
  int cases = 0;
  int probedModelFailures = 0;  // exact failures against a probed profile
};

// Systems in the order they first appear in `results`.
std::vector<std::pair<std::string, SystemJudgement>> judgementCounts(const std::vector<CaseResult>& results);

// {"<system>": {"judged_by": {"exact": n, ..., "none": n}, "outcomes": {"pass": n, ...}, "cases": n,
//               "probed_model_failures": n}}
nlohmann::json judgementJson(const std::vector<CaseResult>& results);

// One line per system: "  sparsegrid: 166 judged by exact, 0 by envelope, ...; 18 not judged (skip)".
std::string judgementLines(const std::vector<CaseResult>& results);

}  // namespace voxref::conf
