#include "conformance/framework/report/report_files.h"

#include <ctime>

#include "conformance/framework/report/html_report.h"
#include "conformance/framework/report/junit_xml.h"
#include "conformance/io/atomic_file.h"

namespace voxref::conf {

void writeReportFiles(const std::filesystem::path& outDir, const RunInfo& run, const std::vector<CaseResult>& results) {
  io::writeFileAtomically(outDir / "results.json", resultsText(run, results));
  io::writeFileAtomically(outDir / "junit.xml", junitXml(results));
  writeHtmlReport(outDir, run, results);
}

std::string utcTimestamp() {
  const std::time_t t = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

}  // namespace voxref::conf
