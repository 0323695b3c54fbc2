// Temporary files that a signal does not leave behind. An output is written to a temporary file
// and renamed into place when complete (atomic_file.h); an exception removes the temporary as it
// unwinds, but SIGINT, SIGTERM or SIGHUP would end the process without unwinding and leave it
// (for a decode of the paper's largest volume, 32 GB of hidden files beside the outputs).
#pragma once

#include <filesystem>

namespace voxref::io {

// While a guard lives, its path is removed if this process is ended by SIGINT, SIGTERM or SIGHUP
// through the handlers of removeTemporariesOnSignals(). A forked child inherits the registrations
// but never removes its parent's files (each entry remembers the process that made it). At most
// kMaxGuardedTemporaries paths of up to 4095 bytes are guarded at once; a path beyond that is not
// guarded (the destructors still remove it on every ordinary exit and exception). Thread-safe.
inline constexpr int kMaxGuardedTemporaries = 64;
class TemporaryFileGuard {
 public:
  explicit TemporaryFileGuard(const std::filesystem::path& path);
  ~TemporaryFileGuard();
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;
  bool guarded() const { return slot_ >= 0; }

 private:
  int slot_ = -1;
};

// Installs handlers for SIGINT, SIGTERM and SIGHUP (each one the process does not ignore) that
// remove every guarded temporary file of this process and then end it by the same signal with
// its default action, so the exit status still names the signal. Call once, early in main.
// Handlers installed later (isolation/interrupt.h) hand the signal back to these.
void removeTemporariesOnSignals();

}  // namespace voxref::io
