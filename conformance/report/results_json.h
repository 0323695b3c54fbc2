// results.json: the machine-readable report of a run (DESIGN.md, "Command line"): the driver
// (renderer, version, environment pins, CPU flags), the profile, and per case its status, every
// oracle's verdict and figures, the effects simulated and the seconds spent per path.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/case.h"

namespace voxref::conf {

struct RunInfo {
  nlohmann::json driver;       // driverJson()
  std::string command;         // the command line
  std::string started, finished;  // ISO 8601, UTC
  bool complete = true;        // false when the run was interrupted
};

nlohmann::json caseJson(const CaseResult& r);
nlohmann::json resultsJson(const RunInfo& run, const std::vector<CaseResult>& results);

}  // namespace voxref::conf
