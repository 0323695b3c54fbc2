#include "conformance/framework/report/report_files.h"

#include <ctime>

#include "conformance/framework/report/html_report.h"
#include "conformance/framework/report/junit_xml.h"
#include "conformance/framework/report/results_csv.h"
#include "conformance/io/atomic_file.h"

namespace voxref::conf {

void writeReportFiles(const std::filesystem::path& outDir, const RunInfo& run, const std::vector<CaseResult>& results,
                      const JunitOptions& junit) {
  std::vector<OutcomeRow> rows;
  for (const CaseResult& r : results) {
    const Outcome o = parseOutcome(r.outcome).value_or(classify(r.id, &r, r.reruns, Expectations{}));
    rows.push_back({junit.idPrefix + r.id, o, &r});
  }
  for (const std::string& id : run.notRun) rows.push_back({junit.idPrefix + id, Outcome::Missing, nullptr});
  io::writeFileAtomically(outDir / "results.json", resultsText(run, results));
  io::writeFileAtomically(outDir / "junit.xml", junitXml(results, junit));
  io::writeFileAtomically(outDir / "results.csv", resultsCsv(rows));
  io::writeFileAtomically(outDir / "failures.csv", failuresCsv(rows));
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
