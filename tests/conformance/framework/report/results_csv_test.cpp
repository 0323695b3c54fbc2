#include "conformance/framework/report/results_csv.h"

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

CaseResult result(const std::string& id, Status s, double seconds) {
  CaseResult r;
  r.id = id;
  r.status = s;
  r.seconds = seconds;
  return r;
}

TEST(ResultsCsv, ListsEveryCaseAndFailuresCsvIsTheNextFailsFile) {
  const CaseResult pass = result("a.pass", Status::Pass, 1.23456), fail = result("a.fail", Status::Fail, 2.0),
                   expected = result("a.expected", Status::Crash, 0.5), flake = result("a.flake", Status::Fail, 3.0),
                   warn = result("a.warn", Status::Warn, 0.25), better = result("a.better", Status::Pass, 0.125);
  const std::vector<OutcomeRow> rows = {{"p.a.pass", Outcome::Pass, &pass},
                                        {"p.a.fail", Outcome::Fail, &fail},
                                        {"p.a.expected", Outcome::ExpectedFail, &expected},
                                        {"p.a.flake", Outcome::Flake, &flake},
                                        {"p.a.warn", Outcome::Warn, &warn},
                                        {"p.a.better", Outcome::UnexpectedImprovement, &better},
                                        {"p.a.missing", Outcome::Missing, nullptr}};
  EXPECT_EQ(resultsCsv(rows),
            "p.a.pass,Pass,1.235\np.a.fail,Fail,2.000\np.a.expected,ExpectedFail,0.500\np.a.flake,Flake,3.000\n"
            "p.a.warn,Warn,0.250\np.a.better,UnexpectedImprovement(Pass),0.125\np.a.missing,Missing,0.000\n");
  const std::string failures = failuresCsv(rows);
  EXPECT_EQ(failures, "p.a.fail,Fail\np.a.expected,Crash\np.a.warn,Warn\n");
  // Read back as a fails file, it expects exactly what failed: the next run's outcomes are all
  // expected (the improvement has left it).
  std::map<std::string, ExpectedStatus> next;
  parseFailsText(failures, "failures.csv", next);
  Expectations e;
  e.fails = next;
  for (const auto& [id, r] : {std::pair{"p.a.fail", &fail}, {"p.a.expected", &expected}, {"p.a.warn", &warn}})
    EXPECT_EQ(classify(id, r, {}, e), Outcome::ExpectedFail) << id;
  EXPECT_EQ(classify("p.a.better", &better, {}, e), Outcome::Pass);
}

}  // namespace
}  // namespace voxref::conf
