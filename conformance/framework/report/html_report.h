// The HTML report a person reads in a browser: index.html (html_index.h) and one page per case,
// cases/<id>.html (html_case_page.h), beside results.json and the images/ the cases wrote.
// Self-contained: no network, no external script or style; every page checks itself in the
// browser (html_page.h, "Self-check").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/report/results_json.h"

namespace voxref::conf {

// Writes outDir/cases/<id>.html for every result, then outDir/index.html, each atomically
// (io::writeFileAtomically: a reader never sees half a page). A partial run (run.complete ==
// false) says so on every page. Throws io::IoError naming the file that could not be written.
void writeHtmlReport(const std::filesystem::path& outDir, const RunInfo& run, const std::vector<CaseResult>& results);

// The parts of writeHtmlReport, for snapshots written while a run goes on: the index, and the
// page of one case (when it finishes). Atomic; throw io::IoError. A case page shows the run's
// partial banner as it was when written, so the final report should come from writeHtmlReport.
void writeHtmlIndex(const std::filesystem::path& outDir, const RunInfo& run, const std::vector<CaseResult>& results);
void writeHtmlCasePage(const std::filesystem::path& outDir, const RunInfo& run, const CaseResult& result);

// index.html alone (html_index.h); kept for callers that write the file themselves.
std::string htmlReport(const RunInfo& run, const std::vector<CaseResult>& results);

}  // namespace voxref::conf
