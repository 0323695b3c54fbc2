#include "conformance/framework/isolation/child_processes.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <system_error>
#include <vector>

#include "conformance/framework/isolation/interrupt.h"

namespace voxref::conf::isolation {
namespace {

using Clock = std::chrono::steady_clock;

[[noreturn]] void fail(const char* what) { throw std::system_error(errno, std::generic_category(), what); }

struct Running {
  std::size_t index = 0;
  pid_t pid = -1;
  int outputFd = -1, resultFd = -1;  // read ends; -1 once at end of file
  Clock::time_point started;
  ChildOutcome outcome;
  bool killed = false;
};

// Writes all of `text` to `fd` (the child's side of the result pipe).
bool writeAll(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// exit() in the child (a driver or a case may call it) runs the static destructors of the parent's
// libraries; log4cplus (loaded with OpenImageIO) then waits for its thread pool, whose threads
// fork() did not copy, for ever. Registered last, this runs first and ends the process with the
// same status after flushing stdio.
void exitAtOnce(int status, void*) {
  std::fflush(nullptr);
  _exit(status);
}

// The child's side: never returns.
[[noreturn]] void runChild(std::size_t index, const std::function<std::string(std::size_t)>& task, pid_t parent,
                           int outputWrite, int resultWrite) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGTERM);     // as a stop (stopGroup): the child removes its temporaries
  if (getppid() != parent) _exit(125);  // the parent died before the line above
  forgetInterruptsInChild();
  on_exit(exitAtOnce, nullptr);
  dup2(outputWrite, STDOUT_FILENO);
  dup2(outputWrite, STDERR_FILENO);
  close(outputWrite);
  std::string result;
  try {
    result = task(index);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "voxref: the task threw: %s\n", e.what());
    std::fflush(nullptr);
    _exit(3);
  }
  std::fflush(nullptr);
  const bool written = writeAll(resultWrite, result);
  close(resultWrite);
  // _exit: no atexit handlers or static destructors of the parent's copy of the process.
  _exit(written ? 0 : 4);
}

Running start(std::size_t index, const std::function<std::string(std::size_t)>& task) {
  int output[2], result[2];
  if (pipe2(output, O_CLOEXEC) != 0) fail("pipe for a child's output");
  if (pipe2(result, O_CLOEXEC) != 0) {
    close(output[0]);
    close(output[1]);
    fail("pipe for a child's result");
  }
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    for (int fd : {output[0], output[1], result[0], result[1]}) close(fd);
    fail("fork");
  }
  if (pid == 0) {
    close(output[0]);
    close(result[0]);
    runChild(index, task, parent, output[1], result[1]);
  }
  setpgid(pid, pid);  // also here, so that a kill right after fork reaches the group
  close(output[1]);
  close(result[1]);
  fcntl(output[0], F_SETFL, O_NONBLOCK);
  fcntl(result[0], F_SETFL, O_NONBLOCK);
  Running r;
  r.index = index;
  r.pid = pid;
  r.outputFd = output[0];
  r.resultFd = result[0];
  r.started = Clock::now();
  return r;
}

// Reads what is available; closes the descriptor at end of file. With `truncated`, keeps only the
// tail of `into` and sets *truncated when it dropped some.
void drain(int& fd, std::string& into, bool* truncated) {
  char buf[65536];
  for (;;) {
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n > 0) {
      into.append(buf, static_cast<std::size_t>(n));
      if (truncated && into.size() > 2 * kKeptOutputBytes) {
        into.erase(0, into.size() - kKeptOutputBytes);
        *truncated = true;
      }
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
    close(fd);
    fd = -1;
    return;
  }
}

// Waits for the child to end; returns its wait status.
int waitFor(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

// Ends the child's process group and waits for the child: SIGTERM first, whose handler in the
// child removes the temporary files it was writing (io/temporary_files.h; a SIGKILL would leave
// them beside the outputs), then SIGKILL if the child is still there after kStopGraceSeconds (a
// driver that blocks or ignores SIGTERM). Returns the child's wait status.
constexpr double kStopGraceSeconds = 2.0;
int stopGroup(pid_t pid) {
  kill(-pid, SIGTERM);
  const auto deadline = Clock::now() + std::chrono::duration<double>(kStopGraceSeconds);
  int status = 0;
  for (;;) {
    const pid_t ended = waitpid(pid, &status, WNOHANG);
    if (ended == pid || (ended < 0 && errno != EINTR)) return status;
    if (Clock::now() >= deadline) break;
    usleep(5000);
  }
  kill(-pid, SIGKILL);
  return waitFor(pid);
}

// Marks the child as stopped on purpose; reap() stops it.
void killGroup(Running& r, Ending why) {
  if (r.killed) return;
  r.killed = true;
  r.outcome.ending = why;
}

// Waits for the child (stopping it first when it was killed on purpose) and fills the ending from
// its status (unless it was killed on purpose).
void reap(Running& r) {
  for (int fd : {r.outputFd, r.resultFd})
    if (fd >= 0) close(fd);
  r.outputFd = r.resultFd = -1;
  const int status = r.killed ? stopGroup(r.pid) : waitFor(r.pid);
  kill(-r.pid, SIGKILL);  // anything the child left behind in its group
  ChildOutcome& o = r.outcome;
  o.seconds = std::chrono::duration<double>(Clock::now() - r.started).count();
  if (o.output.size() > kKeptOutputBytes) {
    o.output.erase(0, o.output.size() - kKeptOutputBytes);
    o.outputTruncated = true;
  }
  if (r.killed) {
    o.result.clear();
    return;
  }
  if (WIFSIGNALED(status)) {
    o.ending = Ending::Signalled;
    o.signal = WTERMSIG(status);
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !o.result.empty()) {
    o.ending = Ending::Finished;
  } else {
    o.ending = Ending::Exited;
    o.exitStatus = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  if (o.ending != Ending::Finished) o.result.clear();
}

}  // namespace

std::string describe(const ChildOutcome& o, double timeLimitSeconds) {
  char buf[200];
  switch (o.ending) {
    case Ending::Finished:
      return "finished";
    case Ending::Exited:
      std::snprintf(buf, sizeof buf, "the case's process exited with status %d without a result", o.exitStatus);
      return buf;
    case Ending::Signalled:
      std::snprintf(buf, sizeof buf, "the case's process was killed by signal %d (SIG%s: %s)", o.signal,
                    sigabbrev_np(o.signal) ? sigabbrev_np(o.signal) : "?", strsignal(o.signal));
      return buf;
    case Ending::TimedOut:
      std::snprintf(buf, sizeof buf, "the case's process was still running after its time limit of %g s and was killed",
                    timeLimitSeconds);
      return buf;
    case Ending::Interrupted:
      return "the run was interrupted while this case ran";
  }
  return "?";
}

bool runEachInChild(std::size_t count, const PoolOptions& options, const std::function<std::string(std::size_t)>& task,
                    const std::function<void(std::size_t, const ChildOutcome&)>& finished) {
  const int jobs = std::max(1, options.jobs);
  const auto limit =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.timeLimitSeconds));
  const auto tickEvery =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(std::max(options.tickSeconds, 0.01)));
  auto nextTick = Clock::now() + tickEvery;
  std::vector<Running> running;
  // An error in the parent (a report it cannot write, say) leaves through here: its children are
  // stopped and reaped first, so none is cut off by SIGKILL in the middle of writing a file.
  struct StopOnUnwind {
    std::vector<Running>& running;
    ~StopOnUnwind() {
      for (Running& r : running) {
        killGroup(r, Ending::Interrupted);
        reap(r);
      }
    }
  } stopOnUnwind{running};
  std::size_t next = 0;
  for (;;) {
    const bool interrupted = interruptSignal() != 0;
    if (interrupted)
      for (Running& r : running) killGroup(r, Ending::Interrupted);
    while (!interrupted && next < count && running.size() < static_cast<std::size_t>(jobs))
      running.push_back(start(next++, task));
    if (running.empty()) return !interrupted;

    // Children whose pipes are both closed (or that were killed) are reaped and reported.
    for (auto it = running.begin(); it != running.end();) {
      if (it->killed || (it->outputFd < 0 && it->resultFd < 0)) {
        reap(*it);
        const std::size_t index = it->index;
        const ChildOutcome outcome = std::move(it->outcome);
        it = running.erase(it);  // first: a `finished` that throws must not see it reaped again
        finished(index, outcome);
      } else {
        ++it;
      }
    }
    if (running.empty()) continue;

    std::vector<pollfd> fds;
    std::vector<std::pair<Running*, bool>> owners;  // (child, is the output pipe)
    for (Running& r : running) {
      if (r.outputFd >= 0) fds.push_back({r.outputFd, POLLIN, 0}), owners.emplace_back(&r, true);
      if (r.resultFd >= 0) fds.push_back({r.resultFd, POLLIN, 0}), owners.emplace_back(&r, false);
    }
    if (interruptFd() >= 0) fds.push_back({interruptFd(), POLLIN, 0});
    const auto now = Clock::now();
    Clock::duration soonest = std::chrono::seconds(60);
    if (options.timeLimitSeconds > 0)
      for (const Running& r : running) soonest = std::min(soonest, r.started + limit - now);
    if (options.tickSeconds > 0 && options.tick) soonest = std::min(soonest, nextTick - now);
    const int waitMs = static_cast<int>(
        std::clamp<long long>(std::chrono::duration_cast<std::chrono::milliseconds>(soonest).count() + 1, 0, 60000));
    const int ready = poll(fds.data(), fds.size(), waitMs);
    if (ready < 0 && errno != EINTR) fail("poll on the children's pipes");
    for (std::size_t f = 0; f < owners.size(); ++f) {
      if (ready <= 0 || fds[f].revents == 0) continue;
      Running& r = *owners[f].first;
      if (owners[f].second)
        drain(r.outputFd, r.outcome.output, &r.outcome.outputTruncated);
      else
        drain(r.resultFd, r.outcome.result, nullptr);
    }
    const auto after = Clock::now();
    if (options.timeLimitSeconds > 0)
      for (Running& r : running)
        if (after - r.started >= limit) killGroup(r, Ending::TimedOut);
    if (options.tickSeconds > 0 && options.tick && after >= nextTick) {
      options.tick();
      nextTick = after + tickEvery;
    }
  }
}

}  // namespace voxref::conf::isolation
