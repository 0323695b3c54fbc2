#include "conformance/bench/processes.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace voxref::conf {

ProcessRun runVoxref(std::vector<std::string> args) {
  args.insert(args.begin(), "voxref");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);  // its report is not the bench's
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int err = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err) throw std::runtime_error("cannot start voxref " + args[1] + ": " + std::strerror(err));
  // The peak is the process's own VmHWM, polled while it runs: wait4's ru_maxrss would report this
  // (the spawning) process's, which Linux carries over an exec.
  int status = 0;
  ProcessRun r;
  for (;;) {
    std::ifstream statusFile("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(statusFile, line);)
      if (line.rfind("VmHWM:", 0) == 0) r.peakBytes = std::max(r.peakBytes, std::stod(line.substr(6)) * 1024.0);
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) throw std::runtime_error("waiting for voxref " + args[1] + " failed");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("voxref " + args[1] + " failed in the bench (exit status " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status)) + ")");
  return r;
}

void resetPeakResident() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.close();
  if (!clear) throw std::runtime_error("cannot reset the peak resident memory (/proc/self/clear_refs)");
}

double peakResidentBytes() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024.0;
  throw std::runtime_error("no VmHWM in /proc/self/status");
}

}  // namespace voxref::conf
