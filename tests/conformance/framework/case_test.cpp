#include "conformance/framework/case.h"

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

// Every case that is not a pass states its reason in one line: the first failing oracle, else the
// first warning one; a pass has none.
TEST(ConcludeFromOracles, TheStatusAndItsOneLineReason) {
  CaseResult r;
  r.oracles = {{"exact", Verdict::Pass, "0 of 9 samples differ", {}},
               {"envelope", Verdict::Warn, "2 quality warnings", {}},
               {"mesh_image", Verdict::Fail, "5 coverage failures\nsecond line", {}},
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
  r.oracles = {{"occlusion", Verdict::Fail, "", {}}};
  concludeFromOracles(r);
  EXPECT_EQ(r.message, "occlusion: (no summary)");
}

}  // namespace
}  // namespace voxref::conf
