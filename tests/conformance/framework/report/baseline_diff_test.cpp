#include "conformance/framework/report/baseline_diff.h"

#include <gtest/gtest.h>

#include <sstream>

namespace voxref::conf {
namespace {

CaseResult result(const std::string& id, Status status, int mismatched) {
  CaseResult r;
  r.id = id;
  r.status = status;
  r.oracles = {{"exact",
                status == Status::Fail ? Verdict::Fail : Verdict::Pass,
                "",
                {{"mismatched_pixels", mismatched}, {"note", "text"}}}};
  return r;
}

TEST(BaselineDiff, SortsEveryKindOfChange) {
  const std::vector<CaseResult> before = {result("a.same", Status::Pass, 0),   result("b.breaks", Status::Pass, 0),
                                          result("c.fixed", Status::Fail, 12), result("d.moves", Status::Fail, 3),
                                          result("e.warns", Status::Pass, 0),  result("f.skips", Status::Pass, 0),
                                          result("g.gone", Status::Pass, 0),   result("h.crash", Status::Crash, 0)};
  const std::vector<CaseResult> after = {result("a.same", Status::Pass, 0),  result("b.breaks", Status::Fail, 5),
                                         result("c.fixed", Status::Pass, 0), result("d.moves", Status::Fail, 4),
                                         result("e.warns", Status::Warn, 0), result("f.skips", Status::Skip, 0),
                                         result("n.new", Status::Pass, 0),   result("h.crash", Status::Timeout, 0)};
  const BaselineDiff d = compareWithBaseline(before, after);
  EXPECT_TRUE(d.regressed());
  EXPECT_EQ(d.compared, 7u);
  ASSERT_EQ(d.newlyFailing.size(), 1u);
  EXPECT_EQ(d.newlyFailing[0].id, "b.breaks");
  ASSERT_EQ(d.newlyFailing[0].moved.size(), 1u);
  EXPECT_EQ(d.newlyFailing[0].moved[0].figure, "mismatched_pixels");
  EXPECT_EQ(d.newlyFailing[0].moved[0].before, 0);
  EXPECT_EQ(d.newlyFailing[0].moved[0].after, 5);
  ASSERT_EQ(d.newlyWarning.size(), 1u);
  EXPECT_EQ(d.newlyWarning[0].id, "e.warns");
  ASSERT_EQ(d.fixed.size(), 1u);
  EXPECT_EQ(d.fixed[0].id, "c.fixed");
  ASSERT_EQ(d.otherStatus.size(), 2u);  // pass -> skip, crash -> timeout: changes, neither a regression nor a fix
  EXPECT_EQ(d.otherStatus[0].id, "f.skips");
  EXPECT_EQ(d.otherStatus[1].id, "h.crash");
  ASSERT_EQ(d.figuresMoved.size(), 1u);
  EXPECT_EQ(d.figuresMoved[0].id, "d.moves");
  EXPECT_EQ(d.added, std::vector<std::string>{"n.new"});
  EXPECT_EQ(d.missing, std::vector<std::string>{"g.gone"});

  const nlohmann::json j = baselineJson(d, "old/results.json");
  EXPECT_EQ(j["regressed"], true);
  EXPECT_EQ(j["newly_failing"][0]["figures_moved"][0]["after"], 5);
  std::ostringstream text;
  printBaselineDiff(text, d, "old/results.json");
  EXPECT_NE(text.str().find("REGRESSED  b.breaks: pass -> fail; exact.mismatched_pixels 0 -> 5"), std::string::npos)
      << text.str();
}

TEST(BaselineDiff, IdenticalRunsShowNothing) {
  const std::vector<CaseResult> run = {result("a", Status::Pass, 0), result("b", Status::Fail, 2)};
  const BaselineDiff d = compareWithBaseline(run, run);
  EXPECT_FALSE(d.regressed());
  EXPECT_TRUE(d.fixed.empty() && d.otherStatus.empty() && d.figuresMoved.empty() && d.added.empty() &&
              d.missing.empty());
  EXPECT_EQ(d.compared, 2u);
}

}  // namespace
}  // namespace voxref::conf
