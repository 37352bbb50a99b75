#include "fapc/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "fapc/report.hpp"

namespace fapc::cli {

std::string clock_text(double seconds) {
  const auto whole = static_cast<std::int64_t>(std::llround(std::max(0.0, seconds)));
  char text[32];
  if (whole >= 3600)
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", static_cast<long long>(whole / 3600),
                  static_cast<long long>(whole / 60 % 60), static_cast<long long>(whole % 60));
  else
    std::snprintf(text, sizeof text, "%lld:%02lld", static_cast<long long>(whole / 60),
                  static_cast<long long>(whole % 60));
  return text;
}

std::string progress_line(std::string_view what, std::int64_t done, std::int64_t total, double elapsed_seconds,
                          int width) {
  const double fraction =
      total > 0 ? std::clamp(static_cast<double>(done) / static_cast<double>(total), 0.0, 1.0) : 0.0;
  const auto filled = static_cast<int>(std::floor(fraction * width));
  std::string line = "[" + std::string(static_cast<std::size_t>(filled), '#') +
                     std::string(static_cast<std::size_t>(width - filled), '.') + "] " + std::to_string(done) + "/" +
                     std::to_string(total);
  if (!what.empty()) line += " " + std::string(what);
  if (done > 0 && elapsed_seconds > 0) {
    const double rate = static_cast<double>(done) / elapsed_seconds;
    char text[32];
    std::snprintf(text, sizeof text, rate >= 10 ? "%.0f/s" : "%.1f/s", rate);
    line += "  " + std::string(text);
    if (done < total) line += "  " + clock_text(static_cast<double>(total - done) / rate) + " left";
  }
  return line;
}

bool progress_wanted() { return ::isatty(STDERR_FILENO) != 0 && verbosity() != Verbosity::quiet; }

ProgressBar::ProgressBar(bool enabled)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

ProgressBar::~ProgressBar() {
  if (enabled_ && drawn_ > 0) std::cerr << '\r' << std::string(drawn_, ' ') << '\r' << std::flush;
}

void ProgressBar::update(std::string_view what, std::int64_t done, std::int64_t total) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (done < total && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  std::string line = progress_line(what, done, total, std::chrono::duration<double>(now - start_).count());
  const std::size_t length = line.size();
  if (length < drawn_) line += std::string(drawn_ - length, ' ');
  drawn_ = length;
  std::cerr << '\r' << line << std::flush;
}

}  // namespace fapc::cli
