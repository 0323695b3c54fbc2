#include "conformance/framework/isolation/child_processes.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <thread>

#include "conformance/io/temporary_files.h"
#include "tests/scratch_folder.h"

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

// What voxref's main installs (io::removeTemporariesOnSignals), for the tests below, and the
// handlers this test process had before, put back afterwards.
class WithTemporariesRemovedOnSignals {
 public:
  WithTemporariesRemovedOnSignals() {
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], nullptr, &before_[i]);
    io::removeTemporariesOnSignals();
  }
  ~WithTemporariesRemovedOnSignals() {
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &before_[i], nullptr);
  }

 private:
  static constexpr int kSignals[3] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction before_[3]{};
};

// A child stopped while it writes a temporary file: the handlers voxref installs, a scratch
// folder, and in it the temporary (guarded, as AtomicOutput guards it) and its marker.
class StoppedWhileWriting : public ::testing::Test {
 protected:
  // In a child: makes the temporary, then the marker (unguarded: it stays, and shows that the
  // temporary was there), and waits for ever.
  [[noreturn]] void writeTemporaryAndHang() const {
    std::ofstream(temporary_) << "half an image";
    const io::TemporaryFileGuard guard(temporary_);
    std::ofstream(started_) << "the temporary is there";
    for (;;) pause();
  }
  // Waits up to 30 s for the marker.
  bool started() const {
    for (int i = 0; i < 3000 && !std::filesystem::exists(started_); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return std::filesystem::exists(started_);
  }
  bool temporaryLeft() const { return std::filesystem::exists(temporary_); }

 private:
  const WithTemporariesRemovedOnSignals handlers_;
  const test::ScratchFolder dir_;
  const std::filesystem::path temporary_ = dir_ / "image.tmp1.png";
  const std::filesystem::path started_ = temporary_.string() + ".started";
};

// A child stopped at its time limit is sent SIGTERM, so its handler removes the temporary file it
// was writing; SIGKILL would leave it beside the outputs.
TEST_F(StoppedWhileWriting, AtItsTimeLimitTheChildRemovesItsTemporary) {
  PoolOptions options;
  options.timeLimitSeconds = 3;
  const auto o = runAll(1, options, [&](std::size_t) -> std::string { writeTemporaryAndHang(); });
  EXPECT_EQ(o.at(0).ending, Ending::TimedOut);
  ASSERT_TRUE(started()) << "the child never made its temporary";
  EXPECT_FALSE(temporaryLeft()) << "the stopped child left its temporary";
}

// An exception out of the parent's callback (a report it cannot write) leaves runEachInChild only
// after the running children are stopped and reaped: the one writing a file removes it first.
// Task 0 returns once task 1's temporary exists, so the error comes while task 1 holds it.
TEST_F(StoppedWhileWriting, AnErrorInTheParentStopsItsChildrenFirst) {
  PoolOptions options;
  options.jobs = 2;
  const auto task = [&](std::size_t i) -> std::string {
    if (i == 1) writeTemporaryAndHang();
    return started() ? "task 1 is writing" : "task 1 never wrote";
  };
  std::string told;
  EXPECT_THROW(runEachInChild(2, options, task,
                              [&](std::size_t, const ChildOutcome& o) {
                                told = o.result;
                                throw std::runtime_error("cannot write results.json: File too large");
                              }),
               std::runtime_error);
  EXPECT_EQ(told, "task 1 is writing");
  EXPECT_FALSE(temporaryLeft()) << "the child was cut off while writing";
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1) << "a child is left unreaped";
  EXPECT_EQ(errno, ECHILD);
}

}  // namespace
}  // namespace voxref::conf::isolation
