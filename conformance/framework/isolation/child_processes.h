// Running pieces of work each in its own child process, a few at a time, with a time limit:
// what lets `voxref conform` survive a driver that crashes, aborts or hangs (issue 6).
//
// Each task runs in a child made by fork(), without exec: the parent holds no GL context, so the
// child starts from a clean copy of the catalogue and makes its own. The parent's only other
// threads are idle library pools (log4cplus's, loaded with OpenImageIO), which fork() does not
// copy; an exit() in the child therefore ends it at once with its status (on_exit) instead of
// running the destructors that would wait for them. The child is the leader of
// its own process group (setpgid), is sent SIGTERM when the parent dies (PR_SET_PDEATHSIG) and
// has its standard output and error captured into one pipe; its result travels back through a
// second pipe. A child is stopped (its time is up, the run is interrupted, or the parent meets an
// error and leaves runEachInChild by an exception) by SIGTERM to its whole process group, whose
// handler removes the temporary files the child was writing (io/temporary_files.h), then SIGKILL
// if it is still there 2 s later; the parent waits for it either way. The parent never runs a task
// itself, so nothing a task does (SIGSEGV in the driver, abort(), an endless loop, exit(3)) can
// end or stall the run.
//
// Not thread-safe: call from one thread of the parent, which must not hold a GL context.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace voxref::conf::isolation {

// How a child ended.
enum class Ending {
  Finished,     // exited with status 0 after writing its result
  Exited,       // exited with a non-zero status, or with status 0 but no result
  Signalled,    // killed by a signal it raised or received (SIGSEGV, SIGABRT, ...)
  TimedOut,     // still running at its deadline; killed
  Interrupted,  // killed because the run was interrupted (interrupt.h)
};

struct ChildOutcome {
  Ending ending = Ending::Finished;
  int exitStatus = 0;  // Exited
  int signal = 0;      // Signalled
  std::string result;  // what the task returned (Finished only)
  std::string output;  // the child's stdout and stderr, interleaved; the last kKeptOutputBytes
  bool outputTruncated = false;
  double seconds = 0.0;  // wall time from fork to end
};

inline constexpr std::size_t kKeptOutputBytes = 64 * 1024;

// "killed by signal 11 (SIGSEGV: Segmentation fault)" and the like, for reports.
std::string describe(const ChildOutcome& outcome, double timeLimitSeconds);

struct PoolOptions {
  int jobs = 1;                   // children at once (>= 1)
  double timeLimitSeconds = 300;  // per task, from its fork; <= 0: no limit
  double tickSeconds = 0;         // > 0: call `tick` in the parent at least this often
  std::function<void()> tick;
};

// Runs task(i) for every i in [0, count), each in its own child, at most `options.jobs` at once,
// starting them in index order. `task` runs in the child and returns the result text;
// `finished(i, outcome)` runs in the parent as each child ends (in the order they end).
// Stops starting tasks once interrupt.h reports an interruption, stops the running children
// (reported as Interrupted) and returns false; true when every task ran.
// Throws std::system_error when a pipe or fork cannot be made, and passes on what `finished` or
// `options.tick` throws; either way every running child is stopped and reaped first.
bool runEachInChild(std::size_t count, const PoolOptions& options, const std::function<std::string(std::size_t)>& task,
                    const std::function<void(std::size_t, const ChildOutcome&)>& finished);

}  // namespace voxref::conf::isolation
