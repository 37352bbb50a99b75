#include "column_picks.hpp"

#include <algorithm>
#include <cmath>

#include "plot_geometry.hpp"

namespace fapc::pipeline::plot {

double time_to_x(double t, double duration) {
  return kLeft + kInset + (kWidth - kLeft - kRight - 2 * kInset) * t / duration;
}

void ColumnPicks::add(double t, double v) {
  const Pick point{added_, t, v};
  // Without a duration every point is drawn as a dot (draw.cpp): each has a column of its own.
  const double column = duration_ > 0 ? std::floor(time_to_x(t, duration_)) : static_cast<double>(added_);
  if (added_ > 0 && column == column_) {
    // The first of equal extremes is kept: strict comparisons.
    if (v < low_.v) low_ = point;
    if (v > high_.v) high_ = point;
  } else {
    if (added_ > 0) flush();
    first_ = low_ = high_ = point;
    column_ = column;
  }
  last_ = point;
  ++added_;
}

void ColumnPicks::flush() {
  Pick picks[] = {first_, low_, high_, last_};
  std::sort(std::begin(picks), std::end(picks), [](const Pick& a, const Pick& b) { return a.index < b.index; });
  for (std::size_t k = 0; k < 4; ++k)
    if (k == 0 || picks[k].index != picks[k - 1].index) picks_.emplace_back(picks[k].t, picks[k].v);
}

Points ColumnPicks::take() {
  if (added_ > 0) flush();
  added_ = 0;
  return std::exchange(picks_, {});
}

}  // namespace fapc::pipeline::plot
