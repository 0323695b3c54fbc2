#include "conformance/framework/report/judgement_counts.h"

#include <gtest/gtest.h>

namespace voxref::conf {
namespace judgement_counts_test {

CaseResult result(const char* system, Status status, Judge judge, bool probedFail = false) {
  CaseResult r;
  r.system = system;
  r.status = status;
  r.judgedBy = judge;
  r.probedModelFailed = probedFail;
  return r;
}

TEST(JudgementCounts, PerSystemInFirstSeenOrder) {
  const std::vector<CaseResult> results = {
      result("sparsegrid", Status::Pass, Judge::Exact), result("sparsegrid", Status::Skip, Judge::None),
      result("iso", Status::Pass, Judge::IsoGeometry), result("sparsegrid", Status::Fail, Judge::Exact, true)};
  const auto counts = judgementCounts(results);
  ASSERT_EQ(counts.size(), 2u);
  EXPECT_EQ(counts[0].first, "sparsegrid");
  EXPECT_EQ(counts[0].second.cases, 3);
  EXPECT_EQ(counts[0].second.judgedBy.at(Judge::Exact), 2);
  EXPECT_EQ(counts[0].second.judgedBy.at(Judge::None), 1);
  EXPECT_EQ(counts[0].second.probedModelFailures, 1);
  const nlohmann::json j = judgementJson(results);
  EXPECT_EQ(j["sparsegrid"]["judged_by"]["none"], 1);
  EXPECT_EQ(j["sparsegrid"]["outcomes"]["skip"], 1);
  EXPECT_EQ(j["iso"]["judged_by"]["iso_geometry"], 1);
  EXPECT_EQ(judgementLines(results),
            "  sparsegrid: 3 case(s); judged on GL by 2 exact; not judged 1; 1 exact failure(s) against the probed "
            "profile: the probed model does not hold here\n"
            "  iso: 1 case(s); judged on GL by 1 iso_geometry; not judged 0\n");
}

}  // namespace judgement_counts_test
}  // namespace voxref::conf
