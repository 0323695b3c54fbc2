#include "conformance/framework/report/results_csv.h"

#include <cstdio>

namespace voxref::conf {

std::string resultsCsv(const std::vector<OutcomeRow>& rows) {
  std::string out;
  for (const OutcomeRow& r : rows) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3f", r.result ? r.result->seconds : 0.0);
    out += r.id + "," + outcomeName(r.outcome, r.result ? r.result->status : Status::Fail) + "," + seconds + "\n";
  }
  return out;
}

std::string failuresCsv(const std::vector<OutcomeRow>& rows) {
  std::string out;
  for (const OutcomeRow& r : rows) {
    if (!r.result || r.outcome == Outcome::Flake || r.outcome == Outcome::KnownFlake) continue;
    const Status s = r.result->status;
    if (!isFailure(s) && s != Status::Warn) continue;
    out += r.id + "," + deqpStatusName(s) + "\n";
  }
  return out;
}

}  // namespace voxref::conf
