#include "conformance/io/temporary_files.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/scratch_folder.h"

namespace voxref::io {
namespace {

void touch(const std::filesystem::path& p) { std::ofstream(p) << "x"; }

// Runs `body` in a child process and returns its wait status.
template <class Body>
int inChild(Body body) {
  const pid_t pid = fork();
  if (pid == 0) {
    body();
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

// A child that makes `path`, guards it while `guardAlive` (else only for a moment), installs the
// handlers and raises `sig`; returns its wait status.
int signalledChild(const std::filesystem::path& path, bool guardAlive, int sig) {
  return inChild([&] {
    touch(path);
    std::optional<TemporaryFileGuard> guard(std::in_place, path);
    if (!guard->guarded()) _exit(3);
    if (!guardAlive) guard.reset();
    removeTemporariesOnSignals();
    raise(sig);
    _exit(4);  // not reached
  });
}

// The guarded file is gone and the child ended by SIGTERM (the exit status names the signal); an
// unguarded file beside it stays.
TEST(TemporaryFiles, ASignalRemovesGuardedFilesAndEndsTheProcessByThatSignal) {
  const test::ScratchFolder dir;
  const auto guarded = dir / "out.tmp1.raw", other = dir / "other.raw";
  touch(other);
  const int status = signalledChild(guarded, true, SIGTERM);
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(std::filesystem::exists(guarded));
  EXPECT_TRUE(std::filesystem::exists(other));
}

// A guard that has gone out of scope protects nothing any more: the file (an output renamed
// into place would have that name no longer, but a later file might) stays.
TEST(TemporaryFiles, AFinishedGuardNoLongerRemovesItsPath) {
  const test::ScratchFolder dir;
  const auto path = dir / "kept.raw";
  const int status = signalledChild(path, false, SIGINT);
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_TRUE(std::filesystem::exists(path));
}

// A forked child inherits its parent's guards but never removes the parent's files.
TEST(TemporaryFiles, AForkedChildLeavesItsParentsFiles) {
  const test::ScratchFolder dir;
  const auto parentsFile = dir / "parent.tmp.raw";
  const int status = inChild([&] {
    touch(parentsFile);
    TemporaryFileGuard guard(parentsFile);
    removeTemporariesOnSignals();
    const int grandchild = inChild([] { raise(SIGTERM); });
    _exit(WIFSIGNALED(grandchild) && WTERMSIG(grandchild) == SIGTERM && std::filesystem::exists(parentsFile) ? 0 : 5);
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the grandchild removed its parent's file, or did not end by SIGTERM";
}

// The table is fixed storage: kMaxGuardedTemporaries paths at once, and a path that does not fit
// a slot is not guarded (and says so); a freed slot is used again.
TEST(TemporaryFiles, GuardsAreBoundedAndSaySoWhenTheyCannotGuard) {
  std::vector<std::unique_ptr<TemporaryFileGuard>> guards;
  for (int i = 0; i < kMaxGuardedTemporaries; ++i)
    guards.push_back(std::make_unique<TemporaryFileGuard>("/nonexistent/" + std::to_string(i)));
  for (const auto& g : guards) EXPECT_TRUE(g->guarded());
  EXPECT_FALSE(TemporaryFileGuard("/nonexistent/one-too-many").guarded());
  guards.pop_back();
  EXPECT_TRUE(TemporaryFileGuard("/nonexistent/again").guarded());
  guards.clear();
  EXPECT_FALSE(TemporaryFileGuard(std::string(5000, 'a')).guarded());
}

}  // namespace
}  // namespace voxref::io
