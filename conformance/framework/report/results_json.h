// results.json: the machine-readable report of a run (docs/design.md, "Command line"): the driver
// (renderer, version, environment pins, CPU flags), the profile, and per case its status, every
// oracle's verdict and figures, the effects simulated and the seconds spent per path.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/framework/case.h"

namespace voxref::conf {

struct RunInfo {
  nlohmann::json driver;                                // driverJson()
  std::string command;                                  // the command line
  std::string started, finished;                        // ISO 8601, UTC
  bool complete = true;                                 // false when the run was interrupted
  bool running = false;                                 // a snapshot written while the run goes on (complete is false)
  std::string interruptedBy;                            // "SIGINT" or "SIGTERM" when !complete
  std::vector<std::string> notRun;                      // ids selected but not run (an interrupted run)
  nlohmann::json execution = nlohmann::json::object();  // isolation, jobs, shard, time limit
  nlohmann::json baseline;                              // baselineJson() when --baseline was given, else null
};

nlohmann::json caseJson(const CaseResult& r);
nlohmann::json resultsJson(const RunInfo& run, const std::vector<CaseResult>& results);
// results.json as written: resultsJson indented by 2, with a final newline. Bytes that are not
// UTF-8 (a crashed case's output cut at an arbitrary byte, a driver's message) become U+FFFD
// instead of making the report unwritable.
std::string resultsText(const RunInfo& run, const std::vector<CaseResult>& results);

}  // namespace voxref::conf
