#include "conformance/io/temporary_files.h"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

namespace voxref::io {
namespace {

// A signal handler may call only async-signal-safe functions and touch lock-free atomics (POSIX.1-2017,
// section 2.4.3): unlink(), getpid() and raise() are on that list, so the table is fixed
// storage that a handler reads without locks or allocation.
enum SlotState : int { kFree = 0, kWriting = 1, kLive = 2 };
struct Slot {
  std::atomic<int> state{kFree};
  std::atomic<pid_t> owner{0};
  char path[4096] = {};
};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<pid_t>::is_always_lock_free);
std::array<Slot, kMaxGuardedTemporaries> gSlots;

void removeAndReraise(int sig) {
  const int saved = errno;
  const pid_t self = getpid();
  for (Slot& s : gSlots)
    if (s.state.load() == kLive && s.owner.load() == self) unlink(s.path);
  errno = saved;
  // SA_RESETHAND restored the default action; the signal is blocked while this runs, so it is
  // delivered, and ends the process, when the handler returns.
  raise(sig);
}

}  // namespace

TemporaryFileGuard::TemporaryFileGuard(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.size() >= sizeof(Slot::path)) return;
  for (int i = 0; i < kMaxGuardedTemporaries; ++i) {
    Slot& s = gSlots[static_cast<std::size_t>(i)];
    int expected = kFree;
    if (!s.state.compare_exchange_strong(expected, kWriting)) continue;
    std::memcpy(s.path, text.c_str(), text.size() + 1);
    s.owner.store(getpid());
    s.state.store(kLive);
    slot_ = i;
    return;
  }
}

TemporaryFileGuard::~TemporaryFileGuard() {
  if (slot_ >= 0) gSlots[static_cast<std::size_t>(slot_)].state.store(kFree);
}

void removeTemporariesOnSignals() {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;  // nohup, a background job
    struct sigaction sa {};
    sa.sa_handler = removeAndReraise;
    sa.sa_flags = SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, nullptr);
  }
}

}  // namespace voxref::io
