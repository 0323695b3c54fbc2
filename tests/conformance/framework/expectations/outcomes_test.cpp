#include "conformance/framework/expectations/outcomes.h"

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

CaseResult withStatus(const std::string& id, Status s) {
  CaseResult r;
  r.id = id;
  r.status = s;
  return r;
}

Expectations expecting(const std::string& fails, const std::string& flakes = "") {
  Expectations e;
  parseFailsText(fails, "fails.txt", e.fails);
  e.flakes = parsePatternsText(flakes, "flakes.txt");
  return e;
}

// deqp-runner's rules, case by case (docs/ci.md, "Outcomes").
TEST(Outcomes, FollowDeqpRunnersRules) {
  const Expectations e = expecting("a.fails,Fail\na.crashes,Crash\na.warns,Warn\n", "^a\\.flaky");
  const auto of = [&](const std::string& id, Status s, std::vector<Status> reruns = {}) {
    const CaseResult r = withStatus(id, s);
    return classify(id, &r, reruns, e);
  };
  EXPECT_EQ(of("a.other", Status::Pass), Outcome::Pass);
  EXPECT_EQ(of("a.other", Status::Skip), Outcome::Skip);
  EXPECT_EQ(of("a.other", Status::Warn), Outcome::Warn);
  EXPECT_EQ(of("a.other", Status::Fail), Outcome::Fail);
  EXPECT_EQ(of("a.other", Status::Crash, {Status::Crash}), Outcome::Crash);
  EXPECT_EQ(of("a.other", Status::Timeout), Outcome::Timeout);
  EXPECT_EQ(of("a.other", Status::Fail, {Status::Fail, Status::Pass}), Outcome::Flake);
  EXPECT_EQ(of("a.fails", Status::Fail), Outcome::ExpectedFail);
  EXPECT_EQ(of("a.crashes", Status::Crash), Outcome::ExpectedFail);
  EXPECT_EQ(of("a.warns", Status::Warn), Outcome::ExpectedFail);
  EXPECT_EQ(of("a.fails", Status::Pass), Outcome::UnexpectedImprovement);
  EXPECT_EQ(of("a.fails", Status::Warn), Outcome::UnexpectedImprovement) << "a warning is better than a failure";
  EXPECT_EQ(of("a.warns", Status::Pass), Outcome::UnexpectedImprovement);
  EXPECT_EQ(of("a.fails", Status::Crash), Outcome::Crash) << "another failure than the expected one";
  EXPECT_EQ(of("a.fails", Status::Skip), Outcome::Skip);
  EXPECT_EQ(of("a.flaky.one", Status::Fail), Outcome::KnownFlake);
  EXPECT_EQ(classify("a.gone", nullptr, {}, e), Outcome::Missing);
}

TEST(Outcomes, OnlyUnexpectedFailuresAreRerun) {
  const Expectations e = expecting("a.fails,Fail\n", "^a\\.flaky");
  EXPECT_TRUE(wantsRerun("a.other", withStatus("a.other", Status::Fail), e));
  EXPECT_TRUE(wantsRerun("a.other", withStatus("a.other", Status::Timeout), e));
  EXPECT_TRUE(wantsRerun("a.fails", withStatus("a.fails", Status::Crash), e));
  EXPECT_FALSE(wantsRerun("a.fails", withStatus("a.fails", Status::Fail), e));
  EXPECT_FALSE(wantsRerun("a.flaky.x", withStatus("a.flaky.x", Status::Fail), e));
  EXPECT_FALSE(wantsRerun("a.other", withStatus("a.other", Status::Warn), e));
}

TEST(Outcomes, WhatFailsTheJobAndTheirNames) {
  for (Outcome o : {Outcome::Fail, Outcome::Crash, Outcome::Timeout, Outcome::UnexpectedImprovement, Outcome::Missing})
    EXPECT_TRUE(failsJob(o)) << outcomeName(o, Status::Pass);
  for (Outcome o :
       {Outcome::Pass, Outcome::Warn, Outcome::Skip, Outcome::ExpectedFail, Outcome::Flake, Outcome::KnownFlake})
    EXPECT_FALSE(failsJob(o)) << outcomeName(o, Status::Pass);
  EXPECT_EQ(outcomeName(Outcome::UnexpectedImprovement, Status::Pass), "UnexpectedImprovement(Pass)");
  EXPECT_EQ(outcomeName(Outcome::UnexpectedImprovement, Status::Warn), "UnexpectedImprovement(Warn)");
  EXPECT_EQ(parseOutcome("UnexpectedImprovement(Pass)"), Outcome::UnexpectedImprovement);
  EXPECT_EQ(parseOutcome("KnownFlake"), Outcome::KnownFlake);
  EXPECT_EQ(parseOutcome("knownflake"), std::nullopt);
}

}  // namespace
}  // namespace voxref::conf
