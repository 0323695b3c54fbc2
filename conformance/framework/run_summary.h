// What `voxref conform` prints when a run ends: a line per case that is not a plain pass (its
// outcome, id and one-line reason), the counts by status, by outcome where expectation files or
// reruns changed any, who judged the cases (report/judgement_counts.h), and the slowest cases.
#pragma once

#include <iosfwd>
#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

// `results` carry their outcome (CaseResult::outcome); `slowest` cases are listed, by seconds.
void printRunSummary(std::ostream& out, const std::vector<CaseResult>& results, int slowest);

}  // namespace voxref::conf
