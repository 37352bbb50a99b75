#include "thin_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fapc {
namespace {

// Longest run of points checked against one chord: bounds the cost on long smooth stretches
// (a kept point every 512 samples costs nothing visible).
constexpr std::size_t kMaxRun = 512;

}  // namespace

void thin_points(std::vector<std::pair<double, double>>& points, double tolerance) {
  if (points.size() <= 2) return;
  double low = points.front().second;
  double high = low;
  for (const auto& [t, v] : points) {
    low = std::min(low, v);
    high = std::max(high, v);
  }
  const double range = high > low ? high - low : std::max(1.0, std::abs(high));
  const double allowed = tolerance * range;

  const auto is_jump = [&](std::size_t i) {
    return (i > 0 && points[i - 1].first == points[i].first) ||
           (i + 1 < points.size() && points[i + 1].first == points[i].first);
  };
  // The lowest and highest value strictly between the anchor and the point after the one
  // looked at: a level chord (a held value) is checked against them alone.
  double run_low = std::numeric_limits<double>::infinity();
  double run_high = -std::numeric_limits<double>::infinity();
  // Can every point strictly between a and b be rebuilt from the chord a-b?
  const auto chord_fits = [&](std::size_t a, std::size_t b) {
    const auto [ta, va] = points[a];
    const auto [tb, vb] = points[b];
    // Level, finite and of positive length, the chord is va at every point (va + 0 * u): the
    // farthest points from it are the lowest and the highest, and the comparisons are those the
    // loop would make for them (NaN values, skipped by the lowest and highest, pass there too).
    if (va == vb && std::isfinite(va) && tb > ta && std::isfinite(tb - ta))
      return run_low > run_high ||  // every point between is NaN
             (!(std::abs(va - run_low) > allowed) && !(std::abs(va - run_high) > allowed));
    for (std::size_t i = a + 1; i < b; ++i) {
      const double u = (points[i].first - ta) / (tb - ta);
      if (std::abs(va + (vb - va) * u - points[i].second) > allowed) return false;
    }
    return true;
  };

  // The kept points are moved to the front of `points` as they are found: the first `kept` slots
  // lie at or before the anchor, and nothing before the anchor is looked at again.
  std::size_t kept = 1;
  std::size_t anchor = 0;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    run_low = std::min(run_low, points[i].second);
    run_high = std::max(run_high, points[i].second);
    const bool droppable = !is_jump(i) && i + 1 - anchor <= kMaxRun && chord_fits(anchor, i + 1);
    if (!droppable) {
      points[kept++] = points[i];
      anchor = i;
      run_low = std::numeric_limits<double>::infinity();
      run_high = -std::numeric_limits<double>::infinity();
    }
  }
  points[kept++] = points.back();
  points.resize(kept);
}

}  // namespace fapc
