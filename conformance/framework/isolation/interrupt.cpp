#include "conformance/framework/isolation/interrupt.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

namespace voxref::conf::isolation {
namespace {

// Signal handlers may touch only lock-free atomics and async-signal-safe calls (POSIX.1-2017,
// section 2.4.3): write() to the pipe, sigaction() and raise(), and the sig_atomic_t below.
volatile sig_atomic_t gSignal = 0;
int gPipe[2] = {-1, -1};
struct sigaction gOldInt, gOldTerm;

// Gives `sig` back to the handler it had before the guard. That handler removes the temporary
// files (io/temporary_files.h) and then takes the default action; a signal the process ignored
// before gets the default action, so that it still ends the process.
void restoreHandlerBeforeGuard(int sig) {
  struct sigaction before = sig == SIGINT ? gOldInt : gOldTerm;
  if (before.sa_handler == SIG_IGN) before.sa_handler = SIG_DFL;
  sigaction(sig, &before, nullptr);
}

void onSignal(int sig) {
  if (gSignal != 0) {  // the second one: what the signal did before the guard, now
    restoreHandlerBeforeGuard(sig);
    raise(sig);
    return;
  }
  gSignal = sig;
  const int saved = errno;
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = write(gPipe[1], &byte, 1);
  errno = saved;
}

}  // namespace

InterruptGuard::InterruptGuard() {
  if (pipe2(gPipe, O_CLOEXEC | O_NONBLOCK) != 0)
    throw std::system_error(errno, std::generic_category(), "pipe for interrupts");
  gSignal = 0;
  struct sigaction sa {};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &gOldInt);
  sigaction(SIGTERM, &sa, &gOldTerm);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &gOldInt, nullptr);
  sigaction(SIGTERM, &gOldTerm, nullptr);
  close(gPipe[0]);
  close(gPipe[1]);
  gPipe[0] = gPipe[1] = -1;
}

int interruptSignal() { return gSignal; }
int interruptFd() { return gPipe[0]; }

void forgetInterruptsInChild() {
  if (gPipe[0] < 0) return;  // no guard: the handlers are those the child should have
  restoreHandlerBeforeGuard(SIGINT);
  restoreHandlerBeforeGuard(SIGTERM);
  close(gPipe[0]);
  if (gPipe[1] >= 0) close(gPipe[1]);
  gPipe[0] = gPipe[1] = -1;
}

}  // namespace voxref::conf::isolation
