// Per pixel column of a panel, the points of a line a reader can tell apart there: the first,
// lowest, highest and last (docs/cli.md, "Plot"). Fed one point at a time in time order, so that a
// line of 10^6 frames costs a few thousand points, whether it was ever held in full or not.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace fapc::pipeline::plot {

using Points = std::vector<std::pair<double, double>>;  // (seconds, value), times ascending

// The x of time `t`, in pixels, on the time axis of a figure `duration` seconds long (> 0).
// Lines of a figure without a duration (a single frame) are drawn point by point: not thinned.
double time_to_x(double t, double duration);

class ColumnPicks {
 public:
  explicit ColumnPicks(double duration) : duration_(duration) {}

  void add(double t, double v);
  // The picks in time order; the object is empty again afterwards.
  Points take();

 private:
  struct Pick {
    std::size_t index = 0;  // among the points added: ties between picks are one point
    double t = 0;
    double v = 0;
  };
  void flush();

  double duration_;
  std::size_t added_ = 0;
  double column_ = 0;
  Pick first_, low_, high_, last_;
  Points picks_;
};

}  // namespace fapc::pipeline::plot
