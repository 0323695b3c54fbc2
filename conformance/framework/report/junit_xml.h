// junit.xml, so that CI systems show the cases: one testsuite per system, one testcase per case;
// fail -> <failure>, crash and timeout -> <error>, skip -> <skipped>, with the message. Where the
// run classified its cases against expectation files (CaseResult::outcome), a case whose outcome
// does not fail the job is not shown as failed: ExpectedFail and KnownFlake are <skipped> with
// the outcome in the message, a Flake is a pass; an UnexpectedImprovement is a <failure>.
#pragma once

#include <string>
#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

struct JunitOptions {
  // At most this many failed testcases (failure or error) are listed; the others are left out
  // and one testcase, voxref.failures_not_listed, says how many (failures.csv has them all), as
  // `deqp-runner junit --limit` does. < 0: no limit.
  int limit = -1;
  // Appended to each failure's message with "{{testcase}}" replaced by the case id, as
  // `deqp-runner junit --template` does ("See https://ci.example/artifacts/{{testcase}}.html").
  std::string linkTemplate;
  std::string idPrefix;  // put before every case id (a suite's entry, docs/ci.md)
};

std::string junitXml(const std::vector<CaseResult>& results, const JunitOptions& options = {});
std::string xmlEscape(const std::string& s);

}  // namespace voxref::conf
