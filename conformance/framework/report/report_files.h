// The files of a report, written together: results.json, junit.xml, results.csv, failures.csv
// (docs/ci.md) and the HTML pages (index.html, cases/<id>.html), each atomically. `voxref conform` and `voxref
// check-shader` both write their reports with it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/report/junit_xml.h"
#include "conformance/framework/report/results_json.h"

namespace voxref::conf {

// Throws io::IoError naming a file that could not be written; files already written stay whole.
// The CSV files list the results (by CaseResult::outcome, else by status) and then every id of
// run.notRun as Missing; ids carry junit.idPrefix.
void writeReportFiles(const std::filesystem::path& outDir, const RunInfo& run, const std::vector<CaseResult>& results,
                      const JunitOptions& junit = {});

// Now, as RunInfo::started and finished hold it: ISO 8601 in UTC ("2026-11-22T02:10:00Z").
std::string utcTimestamp();

}  // namespace voxref::conf
