// results.csv and failures.csv, as deqp-runner writes them (docs/ci.md, "Files of a run"):
// results.csv is `id,outcome,duration` for every case of the run (duration: seconds of its
// process, three decimals), failures.csv is `id,Status` for every case whose status is Fail, Crash,
// Timeout or Warn, expected or not, and not a flake: the next fails file as it is. Both in the
// order of the catalogue, with no header line (deqp-runner writes none).
#pragma once

#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/expectations/outcomes.h"

namespace voxref::conf {

// One case of the run as the CSV files list it; `result` is null for a Missing case.
struct OutcomeRow {
  std::string id;  // with the run's --prefix
  Outcome outcome = Outcome::Pass;
  const CaseResult* result = nullptr;
};

std::string resultsCsv(const std::vector<OutcomeRow>& rows);
std::string failuresCsv(const std::vector<OutcomeRow>& rows);

}  // namespace voxref::conf
