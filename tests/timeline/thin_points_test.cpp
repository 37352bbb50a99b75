// Thinning keeps exactly the points the plain rule keeps: a point goes when every point since the
// last kept one lies within the tolerance of the chord to the point after it. The reference below
// is that rule checked point by point (the thinner takes a level chord against the lowest and
// highest values instead), over held stretches, slopes, jumps, infinities and NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "thin_points.hpp"

namespace fapc {
namespace {

using Points = std::vector<std::pair<double, double>>;

Points thin_by_the_rule(const Points& points, double tolerance) {
  if (points.size() <= 2) return points;
  double low = points.front().second, high = low;
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
  const auto fits = [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a + 1; i < b; ++i) {
      const double u = (points[i].first - points[a].first) / (points[b].first - points[a].first);
      if (std::abs(points[a].second + (points[b].second - points[a].second) * u - points[i].second) > allowed)
        return false;
    }
    return true;
  };
  Points kept{points.front()};
  std::size_t anchor = 0;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    if (is_jump(i) || i + 1 - anchor > 512 || !fits(anchor, i + 1)) {
      kept.push_back(points[i]);
      anchor = i;
    }
  }
  kept.push_back(points.back());
  return kept;
}

bool same(const Points& a, const Points& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const bool values = a[i].second == b[i].second || (std::isnan(a[i].second) && std::isnan(b[i].second));
    if (a[i].first != b[i].first || !values) return false;
  }
  return true;
}

TEST(ThinPoints, KeepsWhatThePointByPointRuleKeeps) {
  std::mt19937 random(11);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (int round = 0; round < 400; ++round) {
    Points points;
    double t = 0, v = 0;
    const int n = 2 + static_cast<int>(random() % 1500);
    for (int i = 0; i < n; ++i) {
      switch (random() % (round % 2 == 0 ? 12 : 300)) {  // odd rounds: long held stretches
        case 0:
          v += static_cast<double>(random() % 100) / 10;
          break;  // a step
        case 1:
          v = std::sin(t);
          break;  // a curve
        case 2:
          points.emplace_back(t, v);
          v += 1;
          break;  // a jump: two points at t
        case 3:
          if (round % 7 == 0) v = (random() % 2) ? inf : nan;
          break;  // what no curve should hold
        case 4:
          if (round % 7 == 0) v = 0;
          break;
        case 5:  // a dip below a held value
          points.emplace_back(t, v - (random() % 2 ? 1e-8 : 0.3));
          t += 0.04;
          break;
        default:
          break;  // held
      }
      if (round % 5 == 0) v += 1e-9 * static_cast<double>(random() % 3);  // nearly held
      points.emplace_back(t, v);
      t += 0.04;
    }
    for (const double tolerance : {0.0, 1e-6, 0.01}) {
      Points thinned = points;
      thin_points(thinned, tolerance);
      ASSERT_TRUE(same(thinned, thin_by_the_rule(points, tolerance)))
          << "round " << round << ", tolerance " << tolerance;
    }
  }
}

}  // namespace
}  // namespace fapc
