// Time and peak resident memory of a bench step: a voxref command run as a process of its own, or
// a step run in this process between resetPeakResident() and peakResidentBytes(). Linux only
// (/proc).
#pragma once

#include <string>
#include <vector>

namespace voxref::conf {

struct ProcessRun {
  double seconds = 0.0;
  double peakBytes = 0.0;  // the process's peak resident memory (VmHWM)
};

// Runs this executable with `args` (argv[1...]), its standard output discarded, and waits for it;
// throws std::runtime_error naming the command unless it exits with 0.
ProcessRun runVoxref(std::vector<std::string> args);

// Sets this process's VmHWM back to its current resident memory (/proc/self/clear_refs, "5"):
// the next peakResidentBytes() is the peak of what ran in between. Throws std::runtime_error when
// the kernel refuses.
void resetPeakResident();
double peakResidentBytes();

}  // namespace voxref::conf
