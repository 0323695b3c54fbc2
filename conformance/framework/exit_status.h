// How voxref's commands end: the exit statuses (README.md, docs/design.md) and the error of a
// mistake in the command.
#pragma once

#include <stdexcept>

namespace voxref::conf {

// A mistake in the command (unknown case, unknown profile, bad option value, unreadable
// baseline): exit status 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Exit statuses of `voxref conform` (0 only when nothing failed); the other commands use 0 and 2.
inline constexpr int kExitPass = 0;       // nothing failed, crashed or timed out
inline constexpr int kExitFailed = 1;     // some case failed, crashed or timed out (none newly, with --baseline)
inline constexpr int kExitUsage = 2;      // bad usage or bad input
inline constexpr int kExitRegressed = 3;  // with --baseline: some case newly failing or newly warning
// An interrupted run exits with 128 + the signal number, as a shell reports it.

}  // namespace voxref::conf
