#include "conformance/framework/report/html_report.h"

#include "conformance/framework/report/html_case_page.h"
#include "conformance/framework/report/html_escape.h"
#include "conformance/framework/report/html_index.h"
#include "conformance/io/atomic_file.h"

namespace voxref::conf {

void writeHtmlIndex(const std::filesystem::path& outDir, const RunInfo& run, const std::vector<CaseResult>& results) {
  io::writeFileAtomically(outDir / "index.html", htmlIndex(run, results));
}

void writeHtmlCasePage(const std::filesystem::path& outDir, const RunInfo& run, const CaseResult& result) {
  io::ensureDirectory(outDir / "cases");
  io::writeFileAtomically(outDir / casePageName(result.id), htmlCasePage(run, result));
}

void writeHtmlReport(const std::filesystem::path& outDir, const RunInfo& run, const std::vector<CaseResult>& results) {
  for (const CaseResult& r : results) writeHtmlCasePage(outDir, run, r);
  writeHtmlIndex(outDir, run, results);
}

std::string htmlReport(const RunInfo& run, const std::vector<CaseResult>& results) { return htmlIndex(run, results); }

}  // namespace voxref::conf
