// A progress line on standard error for work that takes more than a second: nothing is shown
// before one second has passed; on a terminal the line is redrawn in place, otherwise a line is
// printed at most every five seconds (so that CI logs stay short).
#pragma once

#include <chrono>
#include <string>
#include <string_view>

namespace voxref::conf {

class Progress {
 public:
  Progress(std::string label, long total);
  ~Progress();
  void update(long done, std::string_view detail = {});
  void finish();

 private:
  std::string label_;
  long total_;
  bool tty_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_, lastPrint_;
};

}  // namespace voxref::conf
