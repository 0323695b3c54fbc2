#include "conformance/framework/report/junit_xml.h"

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

CaseResult result(const std::string& id, Status s, const std::string& outcome) {
  CaseResult r;
  r.id = id;
  r.system = "sparsegrid";
  r.status = s;
  r.message = "why " + id;
  r.outcome = outcome;
  return r;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(JunitXml, ShowsAnExpectedFailureAsSkippedAndAFlakeAsAPass) {
  const std::vector<CaseResult> results = {
      result("a.expected", Status::Fail, "ExpectedFail"), result("a.flake", Status::Fail, "Flake"),
      result("a.better", Status::Pass, "UnexpectedImprovement(Pass)"), result("a.fail", Status::Fail, "Fail")};
  const std::string x = junitXml(results);
  EXPECT_NE(x.find("<skipped message=\"ExpectedFail: why a.expected\"/>"), std::string::npos) << x;
  EXPECT_EQ(x.find("why a.flake\""), std::string::npos) << "a flake is no failure: " << x;
  EXPECT_NE(x.find("<failure message=\"UnexpectedImprovement(Pass): the fails file expects"), std::string::npos) << x;
  EXPECT_NE(x.find("<failure message=\"why a.fail\"/>"), std::string::npos) << x;
  EXPECT_NE(x.find("failures=\"2\" errors=\"0\" skipped=\"1\""), std::string::npos) << x;
}

TEST(JunitXml, LimitsTheFailuresListedAndLinksEachOne) {
  std::vector<CaseResult> results;
  for (int i = 0; i < 5; ++i) results.push_back(result("a.f" + std::to_string(i), Status::Fail, "Fail"));
  results.push_back(result("a.pass", Status::Pass, "Pass"));
  JunitOptions o;
  o.limit = 2;
  o.linkTemplate = "See https://ci.example/{{testcase}}.html";
  o.idPrefix = "llvmpipe.";
  const std::string x = junitXml(results, o);
  EXPECT_EQ(count(x, "<failure "), 3) << "two listed and one that counts the rest: " << x;
  EXPECT_NE(x.find("why a.f0 See https://ci.example/llvmpipe.a.f0.html"), std::string::npos) << x;
  EXPECT_EQ(x.find("a.f2"), std::string::npos) << x;
  EXPECT_NE(x.find("3 more failed case(s) not listed (limit 2)"), std::string::npos) << x;
  EXPECT_NE(x.find("name=\"llvmpipe.a.pass\""), std::string::npos) << "passes stay listed: " << x;
  EXPECT_EQ(count(junitXml(results), "<failure "), 5) << "no limit by default";
}

}  // namespace
}  // namespace voxref::conf
