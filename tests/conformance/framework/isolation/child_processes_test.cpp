#include "conformance/framework/isolation/child_processes.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>

namespace voxref::conf::isolation {
namespace {

std::map<std::size_t, ChildOutcome> runAll(std::size_t n, PoolOptions options,
                                           const std::function<std::string(std::size_t)>& task) {
  std::map<std::size_t, ChildOutcome> outcomes;
  EXPECT_TRUE(runEachInChild(n, options, task, [&](std::size_t i, const ChildOutcome& o) {
    EXPECT_FALSE(outcomes.count(i)) << "reported twice: " << i;
    outcomes[i] = o;
  }));
  return outcomes;
}

TEST(ChildProcesses, EveryWayOfEndingIsTold) {
  PoolOptions options;
  options.jobs = 2;
  options.timeLimitSeconds = 2;
  const auto o = runAll(6, options, [](std::size_t i) -> std::string {
    std::fprintf(stderr, "task %zu says hello\n", i);
    switch (i) {
      case 0:
        return "result of 0";
      case 1:
        std::raise(SIGSEGV);
        break;
      case 2:
        std::abort();
      case 3:
        std::exit(7);
      case 4:
        for (;;) pause();
      case 5:
        throw std::runtime_error("thrown");
    }
    return "unreachable";
  });
  ASSERT_EQ(o.size(), 6u);
  EXPECT_EQ(o.at(0).ending, Ending::Finished);
  EXPECT_EQ(o.at(0).result, "result of 0");
  EXPECT_EQ(o.at(1).ending, Ending::Signalled);
  EXPECT_EQ(o.at(1).signal, SIGSEGV);
  EXPECT_EQ(o.at(2).ending, Ending::Signalled);
  EXPECT_EQ(o.at(2).signal, SIGABRT);
  EXPECT_EQ(o.at(3).ending, Ending::Exited);
  EXPECT_EQ(o.at(3).exitStatus, 7);
  EXPECT_EQ(o.at(4).ending, Ending::TimedOut);
  EXPECT_EQ(o.at(5).ending, Ending::Exited);
  EXPECT_EQ(o.at(5).exitStatus, 3);
  EXPECT_NE(o.at(5).output.find("thrown"), std::string::npos);
  for (const auto& [i, outcome] : o) {
    EXPECT_NE(outcome.output.find("task " + std::to_string(i) + " says hello"), std::string::npos) << i;
    if (i != 0) {
      EXPECT_TRUE(outcome.result.empty()) << i;
    }
  }
  EXPECT_NE(describe(o.at(1), 2).find("SIGSEGV"), std::string::npos);
  EXPECT_NE(describe(o.at(4), 2).find("time limit of 2 s"), std::string::npos);
}

TEST(ChildProcesses, LargeResultsAndOutputCrossIntact) {
  PoolOptions options;
  options.jobs = 3;
  const auto o = runAll(5, options, [](std::size_t i) {
    // More than a pipe holds (64 KiB), both ways, so the parent must read while the child writes.
    for (int line = 0; line < 20000; ++line) std::printf("output line %d of task %zu\n", line, i);
    return std::string(1 << 20, static_cast<char>('a' + i));
  });
  ASSERT_EQ(o.size(), 5u);
  for (const auto& [i, outcome] : o) {
    EXPECT_EQ(outcome.ending, Ending::Finished);
    EXPECT_EQ(outcome.result, std::string(1 << 20, static_cast<char>('a' + i)));
    EXPECT_TRUE(outcome.outputTruncated);
    EXPECT_LE(outcome.output.size(), kKeptOutputBytes);
    EXPECT_NE(outcome.output.find("output line 19999 of task " + std::to_string(i)),
              std::string::npos);  // the tail is kept
  }
}

TEST(ChildProcesses, ANoisyTaskIsNotMistakenForAResult) {
  const auto o = runAll(1, {}, [](std::size_t) {
    std::printf("noise on stdout\n");
    return std::string();
  });
  EXPECT_EQ(o.at(0).ending, Ending::Exited) << "an empty result is no result";
}

}  // namespace
}  // namespace voxref::conf::isolation
