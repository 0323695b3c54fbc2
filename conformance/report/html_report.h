// index.html: the report a person reads in a browser. The driver and profile; counts per status
// and per system; departures from GL semantics found; one row per case with the three oracles'
// summaries; for every failing or warned case the rendered, emulated, reference and error-mask
// images side by side; for every case its figures. Self-contained (images are files beside it).
#pragma once

#include <string>
#include <vector>

#include "conformance/case.h"
#include "conformance/report/results_json.h"

namespace voxref::conf {

std::string htmlReport(const RunInfo& run, const std::vector<CaseResult>& results);

}  // namespace voxref::conf
