// Progress on a terminal (docs/cli.md, "Progress"): a bar with done/total, the rate and the time
// left, redrawn in place on standard error. Only when standard error is a terminal and -q is not
// given; otherwise nothing is printed at all, so logs and pipes see no control characters.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>

namespace fapc::cli {

// One line of the bar, `width` columns of bar: "[#####.....] 12/100 items  3.4/s  0:26 left".
// With nothing done yet (or no time passed) the rate and the time left are left out.
std::string progress_line(std::string_view what, std::int64_t done, std::int64_t total, double elapsed_seconds,
                          int width = 30);

// "0:26", "1:02:03".
std::string clock_text(double seconds);

class ProgressBar {
 public:
  // Shows nothing unless `enabled` (see progress_wanted()).
  explicit ProgressBar(bool enabled);
  ~ProgressBar();  // clears the line
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  bool enabled() const { return enabled_; }
  // Redraws at most ten times a second (and always at the end); safe from any thread.
  void update(std::string_view what, std::int64_t done, std::int64_t total);

 private:
  bool enabled_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::size_t drawn_ = 0;  // the length of the line on screen
};

// Standard error is a terminal and -q was not given.
bool progress_wanted();

}  // namespace fapc::cli
