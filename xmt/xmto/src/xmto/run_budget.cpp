#include "xmto/run_budget.hpp"

#include <algorithm>
#include <cmath>

namespace fapc::xmt {

RunBudget RunBudget::inside(const SmilTiming& timing, std::optional<double> implicit) const {
  constexpr double kForever = std::numeric_limits<double>::infinity();
  const std::optional<double> simple = timing.dur ? timing.dur : implicit;
  double active = available;  // at most what the parent leaves
  if (timing.end) active = std::min(active, std::max(0.0, *timing.end - timing.begin.value_or(0)));
  if (timing.repeat_dur) active = std::min(active, *timing.repeat_dur);
  const bool repeats_by_time = timing.repeat_count_indefinite || timing.repeat_dur || timing.repeat_dur_indefinite;
  const double count = timing.repeat_count.value_or(repeats_by_time ? kForever : 1);
  double runs = 1;
  if (simple && *simple > 0) {
    active = std::min(active, *simple * count);
    if (std::isfinite(active))
      runs = std::max(1.0, std::ceil(active / *simple));
    else if (std::isfinite(count))
      runs = std::ceil(count);
  } else if (std::isfinite(count)) {
    runs = std::max(1.0, std::ceil(count));
  }
  return RunBudget{simple.value_or(active), repeats * runs};
}

}  // namespace fapc::xmt
