// Comparing a run with an earlier one (`voxref conform --baseline OLD/results.json`): which
// cases changed status, which are newly failing or fixed, and which moved in their oracles'
// figures (mismatched pixels, max error, RMSE, ... every number an oracle reports at its top
// level, compared exactly: the figures are deterministic, so any move is a change of bits).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/framework/case.h"

namespace voxref::conf {

struct FigureMove {
  std::string oracle, figure;
  double before = 0.0, after = 0.0;
};

struct CaseChange {
  std::string id;
  Status before = Status::Pass, after = Status::Pass;
  std::vector<FigureMove> moved;
};

struct BaselineDiff {
  std::vector<CaseChange> newlyFailing;  // now fail, crash or timeout; before anything else
  std::vector<CaseChange> newlyWarning;  // now warn; before pass
  std::vector<CaseChange> fixed;         // before fail, crash or timeout; now pass or warn
  std::vector<CaseChange> otherStatus;  // any other change of status (to or from skip, warn to pass, crash to fail ...)
  std::vector<CaseChange> figuresMoved;  // same status, some oracle figure moved
  std::vector<std::string> added;        // in this run only
  std::vector<std::string> missing;      // in the baseline only (another filter or shard, or removed)
  std::size_t compared = 0;              // cases in both
  // A regression: a case newly failing or newly warning.
  bool regressed() const { return !newlyFailing.empty() || !newlyWarning.empty(); }
};

// Pure: the difference between the baseline's cases and this run's, matched by id.
BaselineDiff compareWithBaseline(const std::vector<CaseResult>& baseline, const std::vector<CaseResult>& current);

// For results.json ("baseline"): the file compared with and every list above.
nlohmann::json baselineJson(const BaselineDiff& diff, const std::string& baselineFile);

// A few lines for the terminal: counts, then every regression and fix with its figures.
void printBaselineDiff(std::ostream& out, const BaselineDiff& diff, const std::string& baselineFile);

}  // namespace voxref::conf
