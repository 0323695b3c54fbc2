// results.json: the machine-readable report of a run (DESIGN.md, "Command line"): the driver
// (renderer, version, environment pins, CPU flags), the profile, and per case its status, every
// oracle's verdict and figures, the effects simulated and the seconds spent per path.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/case.h"

namespace voxref::conf {

struct RunInfo {
  nlohmann::json driver;       // driverJson()
  std::string command;         // the command line
  std::string started, finished;  // ISO 8601, UTC
  bool complete = true;        // false when the run was interrupted
  bool running = false;        // a snapshot written while the run goes on (complete is false)
  std::string interruptedBy;   // "SIGINT" or "SIGTERM" when !complete
  std::vector<std::string> notRun;  // ids selected but not run (an interrupted run)
  nlohmann::json execution = nlohmann::json::object();  // isolation, jobs, shard, time limit
  nlohmann::json baseline;     // baselineJson() when --baseline was given, else null
};

nlohmann::json caseJson(const CaseResult& r);
nlohmann::json resultsJson(const RunInfo& run, const std::vector<CaseResult>& results);

}  // namespace voxref::conf
