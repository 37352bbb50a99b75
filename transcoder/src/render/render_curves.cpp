// Time-value lists (docs/timeline.md, "Rendering"): per target, the blended curve sampled at the
// frame rate plus every key-point time, jumps kept as two points at one time, then thinned.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "thin_points.hpp"
#include "timeline_index.hpp"

namespace fapc {
namespace {

using Points = std::vector<std::pair<double, double>>;

// The times where a clip's curve has a key point, an edge, or a jump, in absolute seconds.
void add_clip_times(const Clip& clip, double end, std::vector<double>& times) {
  times.push_back(clip.begin);
  if (std::isfinite(end)) times.push_back(end);
  if (clip.curve.periodic) return;
  for (const KeyPoint& key : clip.curve.keys) {
    const double t = clip.begin + key.time - clip.curve_offset;
    if (t >= clip.begin && t <= end) times.push_back(t);
  }
}

void add_frame_times(double from, double to, int fps, std::vector<double>& times) {
  for (auto k = static_cast<std::int64_t>(std::ceil(from * fps)); static_cast<double>(k) / fps < to; ++k) {
    times.push_back(static_cast<double>(k) / fps);
  }
}

void sort_unique(std::vector<double>& times) {
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
}

// Samples `value(t, from_left)` at `times`: where the left limit differs from the value (a jump),
// both are kept, the left one first, except before the very first point.
template <class ValueFn>
Points sample(const std::vector<double>& times, ValueFn value) {
  Points points;
  for (const double t : times) {
    const double right = value(t, false);
    if (!points.empty()) {
      const double left = value(t, true);
      if (left != right) points.emplace_back(t, left);
    }
    points.emplace_back(t, right);
  }
  return points;
}

// docs/cli.md: FAP 1 and FAP 2 appear as "viseme" and "expression" curves whose value is the
// number of the strongest weight (0 when none), as for frame inputs; the weights themselves stay
// under their own targets. The number steps, so every change is a jump.
void add_strongest_curve(const TimelineIndex& index, int fap, const char* name, Curves& out) {
  std::vector<std::pair<const TargetIndex*, double>> members;  // with the viseme/expression number
  std::vector<double> times;
  for (const auto& [target, target_index] : index.targets) {
    const std::optional<WeightTarget> weight = weight_target(target);
    if (!weight || weight->fap != fap) continue;
    members.emplace_back(&target_index, weight->number);
    for (std::size_t i = 0; i < target_index.clips.size(); ++i) {
      times.push_back(index.clips[target_index.clips[i]].begin);
      if (std::isfinite(target_index.effective_end[i])) times.push_back(target_index.effective_end[i]);
      add_frame_times(index.clips[target_index.clips[i]].begin,
                      std::min(target_index.effective_end[i], out.duration), out.fps, times);
    }
  }
  if (members.empty()) return;
  sort_unique(times);
  const auto strongest = [&](double t, bool from_left) {
    double best = 0;
    double slot = 0;
    for (const auto& [member, number] : members) {
      const double w = index.value_at(*member, t, from_left).value;
      if (w > best) {
        best = w;
        slot = number;
      }
    }
    return slot;
  };
  Points points;
  for (const double t : times) {
    const double now = strongest(t, false);
    if (!points.empty() && points.back().second != now) points.emplace_back(t, points.back().second);
    points.emplace_back(t, now);
  }
  out.curves[name] = thin_points(std::move(points), 0);
}

}  // namespace

Curves render_curves(const Timeline& timeline, const CurveOptions& options) {
  const TimelineIndex index(timeline.clips);
  Curves out;
  out.fps = options.fps;
  out.duration = timeline.end();
  for (const auto& entry : index.targets) {
    // Not a structured binding: lambdas below capture it (clang 14 cannot capture bindings).
    const TargetIndex& target_index = entry.second;
    std::vector<double> times;
    for (std::size_t i = 0; i < target_index.clips.size(); ++i) {
      const double end = std::min(target_index.effective_end[i], out.duration);
      add_clip_times(index.clips[target_index.clips[i]], end, times);
    }
    const double last = std::min(target_index.span_end, out.duration);
    add_frame_times(target_index.span_begin, last, options.fps, times);
    times.push_back(last);
    sort_unique(times);
    // Captured by name: clang 14 cannot capture a structured binding.
    Points points = sample(times, [&, &targets = target_index](double t, bool from_left) {
      return index.value_at(targets, t, from_left).value;
    });
    out.curves[entry.first] = thin_points(std::move(points), options.tolerance);
  }
  add_strongest_curve(index, 1, "viseme", out);
  add_strongest_curve(index, 2, "expression", out);
  return out;
}

Curves render_clip_curves(const Timeline& timeline, const CurveOptions& options) {
  Curves out;
  out.fps = options.fps;
  out.duration = timeline.end();
  for (const Clip& clip : timeline.clips) {
    std::vector<double> times;
    add_clip_times(clip, clip.end, times);
    add_frame_times(clip.begin, clip.end, options.fps, times);
    sort_unique(times);
    Points points = sample(times, [&](double t, bool from_left) {
      return t >= clip.end && !from_left ? clip_value(clip, t, true) : clip_value(clip, t, from_left);
    });
    // "jaw (table2.mimic:5)"; a second clip from the same place (a macro used twice) gets " #2".
    std::string label = clip.target + " (" +
                        std::filesystem::path(clip.source.file.str()).filename().string() + ":" +
                        std::to_string(clip.source.line) + ")";
    std::string unique = label;
    for (int n = 2; out.curves.contains(unique); ++n) unique = label + " #" + std::to_string(n);
    out.curves[unique] = thin_points(std::move(points), options.tolerance);
  }
  return out;
}

}  // namespace fapc
