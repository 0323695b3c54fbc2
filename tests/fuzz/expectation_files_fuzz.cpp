// libFuzzer target: the CI files a job gives `voxref conform` (conformance/framework/expectations/
// expectation_files.h, docs/ci.md): a fails file, a flakes or skips file and a case list, the same
// bytes read as each of the three, and as a suite file (conformance/framework/suite/suite_file.h);
// then the outcomes against what was read.
//
// Contract under test:
// - parseFailsText, parsePatternsText and parseCaseListText either return or throw
//   ExpectationFileError, parseSuiteText returns or throws SuiteFileError (a TOML syntax error
//   included); nothing else escapes (a std::regex_error neither), nothing reads out of
//   bounds (ASan), no undefined behaviour (UBSan);
// - what a fails file yields round-trips: failuresCsv of cases holding exactly its statuses reads
//   back, as a fails file, to the same map of ids and statuses;
// - classify and wantsRerun run on any expectations read, for every status, without an exception.
// Size cap: none; inputs are as long as libFuzzer's -max_len.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "conformance/framework/expectations/expectation_files.h"
#include "conformance/framework/expectations/outcomes.h"
#include "conformance/framework/report/results_csv.h"
#include "conformance/framework/suite/suite_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voxref::conf;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Expectations e;
  try {
    parseFailsText(text, "fails.txt", e.fails);
  } catch (const ExpectationFileError&) {
    e.fails.clear();
  }
  try {
    e.flakes = parsePatternsText(text, "flakes.txt");
  } catch (const ExpectationFileError&) {
  }
  try {
    for (const ListedCase& c : parseCaseListText(text, "list.txt"))
      if (c.id.empty()) std::abort();  // an accepted id is never empty
  } catch (const ExpectationFileError&) {
  }
  try {
    for (const SuiteEntry& s : parseSuiteText(text, "suite.toml"))
      if (s.name.empty() || s.fraction < 1 || s.flakeReruns < 0) std::abort();  // what the reader promises
  } catch (const SuiteFileError&) {
  }
  // Round trip: the cases failing as the fails file says give it back as failures.csv.
  std::vector<CaseResult> results;
  for (const auto& [id, expected] : e.fails) {
    CaseResult r;
    r.id = id;
    r.status = expected.status;
    results.push_back(r);
  }
  std::vector<OutcomeRow> rows;
  for (const CaseResult& r : results) rows.push_back({r.id, classify(r.id, &r, {}, e), &r});
  std::map<std::string, ExpectedStatus> back;
  parseFailsText(failuresCsv(rows), "failures.csv", back);  // must not throw
  if (back.size() != e.fails.size()) std::abort();
  for (const auto& [id, expected] : e.fails)
    if (!back.count(id) || back.at(id).status != expected.status) std::abort();
  for (const auto& [id, expected] : e.fails)
    for (Status s : {Status::Pass, Status::Warn, Status::Fail, Status::Skip, Status::Crash, Status::Timeout}) {
      CaseResult r;
      r.id = id;
      r.status = s;
      (void)classify(id, &r, {s}, e);
      (void)wantsRerun(id, r, e);
    }
  return 0;
}
