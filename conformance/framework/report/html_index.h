// index.html, the page a person opens first (html_page.h has the frame and its self-check):
//  - the banner of a partial run, the command and its times;
//  - the driver and the profile (or that there is none and the envelope oracle alone judges);
//  - counts per status, overall and per system, each in an element a test can find:
//    id="count-<status>" (all systems) and id="count-<system>-<status>", id="count-cases";
//  - the ids selected but not run (an interrupted run), the execution (isolation, jobs, shard);
//  - the comparison with a baseline run, when there is one (html_baseline.h);
//  - the departures from GL semantics the run found, aggregated over cases;
//  - filters by status, system and text in the id (inline JavaScript; id="shown-count" says how
//    many rows show), and one row per case (id="cases-table", rows carry data-id, data-status,
//    data-system) linking to its page, casePageName(id).
// Every text is escaped; nothing is loaded from outside the report directory.
#pragma once

#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/report/results_json.h"

namespace voxref::conf {

std::string htmlIndex(const RunInfo& run, const std::vector<CaseResult>& results);

}  // namespace voxref::conf
