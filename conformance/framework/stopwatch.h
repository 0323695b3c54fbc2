// Wall-clock seconds of a step (the seconds_* of a case, progress and the command line's reports):
// steady_clock, never compared between runs.
#pragma once

#include <chrono>

namespace voxref::conf {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace voxref::conf
