#include "conformance/framework/case.h"

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

// Every case that is not a pass states its reason in one line: the first failing oracle, else the
// first warning one; a pass has none.
TEST(ConcludeFromOracles, TheStatusAndItsOneLineReason) {
  CaseResult r;
  r.oracles = {{"exact", Verdict::Pass, "0 of 9 samples differ", {}, Judge::Exact},
               {"envelope", Verdict::Warn, "2 quality warnings", {}, Judge::Envelope},
               {"mesh_image", Verdict::Fail, "5 coverage failures\nsecond line", {}, Judge::IsoGeometry},
               {"ideal", Verdict::Info, "rmse 0.1", {}}};
  concludeFromOracles(r);
  EXPECT_EQ(r.status, Status::Fail);
  EXPECT_EQ(r.message, "mesh_image: 5 coverage failures");
  r.oracles[2].verdict = Verdict::Pass;
  concludeFromOracles(r);
  EXPECT_EQ(r.status, Status::Warn);
  EXPECT_EQ(r.message, "envelope: 2 quality warnings");
  r.oracles[1].verdict = Verdict::NotRun;
  concludeFromOracles(r);
  EXPECT_EQ(r.status, Status::Pass);
  EXPECT_EQ(r.message, "");
  EXPECT_EQ(r.judgedBy, Judge::Exact);
  r.oracles = {{"occlusion", Verdict::Fail, "", {}}};
  concludeFromOracles(r);
  EXPECT_EQ(r.message, "occlusion: (no summary)");
}

// Nothing that judged GL's output: a skip with the reason, never a pass; a failure stays a failure.
TEST(ConcludeFromOracles, APassThatJudgedNothingIsASkipWithItsReason) {
  CaseResult r;
  r.oracles = {{"exact", Verdict::NotRun, "no precision profile for this driver", {}, Judge::Exact},
               {"envelope", Verdict::Pass, "all 9 inside; blind here", {}},  // blind: judges nothing
               {"ideal", Verdict::Info, "rmse 0.1", {}}};
  concludeFromOracles(r);
  EXPECT_EQ(r.status, Status::Skip);
  EXPECT_EQ(r.judgedBy, Judge::None);
  EXPECT_EQ(
      r.message,
      "not judged on this driver: exact: no precision profile for this driver; envelope: all 9 inside; blind here");
  r.oracles[1].verdict = Verdict::Fail;
  concludeFromOracles(r);
  EXPECT_EQ(r.status, Status::Fail);
  r.oracles[1].verdict = Verdict::Pass;
  r.oracles[1].judges = Judge::Envelope;
  concludeFromOracles(r);
  EXPECT_EQ(r.status, Status::Pass);
  EXPECT_EQ(r.judgedBy, Judge::Envelope);
}

TEST(MarkProbedModelFailure, OnlyAnExactFailureIsMarked) {
  CaseResult r;
  r.oracles = {{"exact", Verdict::Pass, "0 of 9 samples differ", {}, Judge::Exact},
               {"envelope", Verdict::Fail, "1 outside", {}, Judge::Envelope}};
  concludeFromOracles(r);
  markProbedModelFailure(r);
  EXPECT_FALSE(r.probedModelFailed);
  EXPECT_EQ(r.message, "envelope: 1 outside");
  r.oracles[0] = {"exact", Verdict::Fail, "3 of 9 samples differ", {}, Judge::Exact};
  concludeFromOracles(r);
  markProbedModelFailure(r);
  markProbedModelFailure(r);  // once
  EXPECT_TRUE(r.probedModelFailed);
  EXPECT_EQ(r.message, "the probed model does not hold here: exact: 3 of 9 samples differ");
}

}  // namespace
}  // namespace voxref::conf
