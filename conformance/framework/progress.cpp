#include "conformance/framework/progress.h"

#include <unistd.h>

#include <cstdio>

namespace voxref::conf {

Progress::Progress(std::string label, long total)
    : label_(std::move(label)),
      total_(total),
      tty_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      lastPrint_(start_) {}

Progress::~Progress() { finish(); }

void Progress::update(long done, std::string_view detail) {
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0) return;
  if (!tty_ && shown_ && std::chrono::duration<double>(now - lastPrint_).count() < 5.0) return;
  lastPrint_ = now;
  std::fflush(stdout);  // keep the order of stdout lines and the progress line
  shown_ = true;
  const int width = total_ > 0 ? static_cast<int>(std::to_string(total_).size()) : 1;
  std::fprintf(stderr, "%s[%*ld/%ld] %s %.*s (%.0fs)%s", tty_ ? "\r\033[K" : "", width, done, total_, label_.c_str(),
               static_cast<int>(detail.size()), detail.data(), elapsed, tty_ ? "" : "\n");
  std::fflush(stderr);
}

void Progress::finish() {
  if (shown_ && tty_) std::fprintf(stderr, "\r\033[K");
  shown_ = false;
}

}  // namespace voxref::conf
