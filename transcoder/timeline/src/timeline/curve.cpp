#include <algorithm>
#include <cmath>
#include <numbers>

#include "fapc/timeline/timeline.hpp"

namespace fapc::timeline {
namespace {

// The Mimic fading functions on the fraction u in [0, 1] of a segment (docs/mimic.md,
// "Timing and values").
double shape(Interpolation how, double u) {
  switch (how) {
    case Interpolation::linear:
      return u;
    case Interpolation::step:
      return 0;
    case Interpolation::sin:
      return (1 - std::cos(std::numbers::pi * u)) / 2;
    case Interpolation::log:
      return std::log1p(9 * u) / std::numbers::ln10;
    case Interpolation::exp:
      return (std::pow(10.0, u) - 1) / 9;
  }
  return u;
}

double periodic_value(const Periodic& p, double t) {
  const double span = p.max - p.min;
  if (p.period <= 0) return p.min;
  // A period so short that t / period (times 2 pi) overflows, 1e-320 say: the same phase from
  // what is left of t after whole periods (cos(inf) would be NaN).
  if (!(std::abs(t / p.period) < 1e300)) t = std::fmod(t, p.period);
  if (p.shape == Periodic::Shape::sine) {
    return p.min + span * (1 - std::cos(2 * std::numbers::pi * t / p.period)) / 2;
  }
  double phase = std::fmod(t / p.period, 1.0);
  if (phase < 0) phase += 1;
  return phase < 0.5 ? p.min + span * 2 * phase : p.max - span * (2 * phase - 1);
}

}  // namespace

Curve Curve::constant(double value) { return Curve{{KeyPoint{0, value}}, std::nullopt}; }

Curve Curve::ramp(double from, double to, double duration, Interpolation how) {
  return Curve{{KeyPoint{0, from, how}, KeyPoint{duration, to}}, std::nullopt};
}

namespace {

// The value on the segment that ends at `after` (not the first key).
double on_segment(std::vector<KeyPoint>::const_iterator after, double t) {
  const KeyPoint& a = *(after - 1);
  const KeyPoint& b = *after;
  if (b.time <= a.time) return b.value;
  const double u = (t - a.time) / (b.time - a.time);
  return a.value + (b.value - a.value) * shape(a.to_next, u);
}

}  // namespace

double Curve::value_at(double local_time) const {
  if (periodic) return periodic_value(*periodic, local_time);
  if (keys.empty()) return 0;
  // The segment after the last key at or before t: at two keys at one time the later one wins.
  const auto after =
      std::upper_bound(keys.begin(), keys.end(), local_time, [](double t, const KeyPoint& k) { return t < k.time; });
  if (after == keys.begin()) return keys.front().value;
  if (after == keys.end()) return keys.back().value;
  return on_segment(after, local_time);
}

double Curve::left_limit(double local_time) const {
  if (periodic) return periodic_value(*periodic, local_time);
  if (keys.empty()) return 0;
  // The segment that ends at or after t: at two keys at one time the earlier one counts.
  const auto after =
      std::lower_bound(keys.begin(), keys.end(), local_time, [](const KeyPoint& k, double t) { return k.time < t; });
  if (after == keys.begin()) return keys.front().value;
  if (after == keys.end()) return keys.back().value;
  return on_segment(after, local_time);
}

}  // namespace fapc::timeline
