// Ctrl-C (SIGINT) and SIGTERM during a run. While an InterruptGuard lives, the first such signal
// only records itself (the handler writes one byte to a pipe the run polls), so the run can kill
// its children and write a partial report that says it is partial; a second one goes to the
// handler the guard replaced (voxref's main installs io::removeTemporariesOnSignals, which removes
// the temporary files and ends the process as the signal's default action does).
#pragma once

namespace voxref::conf::isolation {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers; throws std::system_error when the pipe cannot be made
  ~InterruptGuard();  // restores the previous handlers
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// The signal that interrupted the run, or 0. Safe to call without a guard (then always 0).
int interruptSignal();
// A descriptor that becomes readable when the run is interrupted (poll it), or -1 without a guard.
int interruptFd();
// In a forked child: SIGINT and SIGTERM go to the handlers they had before the guard (those of
// io::removeTemporariesOnSignals in voxref, so a child told to stop removes its temporary files;
// the default action where the process ignored the signal), and the parent's pipe is closed.
void forgetInterruptsInChild();

}  // namespace voxref::conf::isolation
