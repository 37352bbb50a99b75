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

// Adds the sample of `value(t, from_left)` at t: where the left limit differs from the value (a
// jump), both are kept, the left one first, except before the very first point.
template <class ValueFn>
void add_sample(Points& points, double t, ValueFn& value) {
  const double right = value(t, false);
  if (!points.empty()) {
    const double left = value(t, true);
    if (left != right) points.emplace_back(t, left);
  }
  points.emplace_back(t, right);
}

template <class ValueFn>
Points sample(const std::vector<double>& times, ValueFn value) {
  Points points;
  for (const double t : times) add_sample(points, t, value);
  return points;
}

// The clips of one target active at ascending times: found by walking forward through its
// elementary intervals (TargetIndex) instead of a binary search per time, which, with the sort of
// every frame time, was most of the curves' cost on long scripts.
class ForwardLookup {
 public:
  explicit ForwardLookup(const TargetIndex& target) : target_(target) {}

  // As TargetIndex::active_at; `t` may not go back between calls with the same `from_left`.
  std::span<const std::uint32_t> active_at(double t, bool from_left) {
    // Interval j is [cuts[j], cuts[j+1]) (from the left: (cuts[j], cuts[j+1]]): j + 1 is the
    // number of cuts at or before t (strictly before, from the left).
    std::size_t& count = from_left ? cuts_before_ : cuts_at_or_before_;
    const std::vector<double>& cuts = target_.cuts;
    while (count < cuts.size() && (from_left ? cuts[count] < t : cuts[count] <= t)) ++count;
    if (count == 0) return {};
    const std::size_t j = count - 1;
    return std::span<const std::uint32_t>(target_.members)
        .subspan(target_.offsets[j], target_.offsets[j + 1] - target_.offsets[j]);
  }

 private:
  const TargetIndex& target_;
  std::size_t cuts_before_ = 0;
  std::size_t cuts_at_or_before_ = 0;
};

// One target's curve at its clips' own times (`clip_times`, sorted, no repeats) and at every frame
// time from `from` to before `to`, in time order, each time once: the frame times are merged in as
// they are counted rather than listed and sorted with the others.
template <class ValueFn>
Points sample_merged(const std::vector<double>& clip_times, double from, double to, int fps, ValueFn value) {
  Points points;
  auto k = static_cast<std::int64_t>(std::ceil(from * fps));
  std::size_t c = 0;
  const auto frame_time = [&] { return static_cast<double>(k) / fps; };
  const auto add = [&](double t) { add_sample(points, t, value); };
  while (true) {
    const bool frames_left = frame_time() < to;
    if (!frames_left && c == clip_times.size()) break;
    if (!frames_left || (c < clip_times.size() && clip_times[c] < frame_time())) {
      add(clip_times[c++]);
    } else {
      const double t = frame_time();
      if (c < clip_times.size() && clip_times[c] == t) ++c;  // the same time from both lists
      add(t);
      ++k;
    }
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
  std::vector<ForwardLookup> lookups;
  for (const auto& member : members) lookups.emplace_back(*member.first);
  const auto strongest = [&](double t, bool from_left) {
    double best = 0;
    double slot = 0;
    for (std::size_t m = 0; m < members.size(); ++m) {
      const double number = members[m].second;
      const double w = blend(index.clips, lookups[m].active_at(t, from_left), t, from_left).value;
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
  for (const auto& [target, target_index] : index.targets) {
    std::vector<double> times;
    for (std::size_t i = 0; i < target_index.clips.size(); ++i) {
      const double end = std::min(target_index.effective_end[i], out.duration);
      add_clip_times(index.clips[target_index.clips[i]], end, times);
    }
    const double last = std::min(target_index.span_end, out.duration);
    times.push_back(last);
    sort_unique(times);
    ForwardLookup lookup(target_index);
    Points points = sample_merged(times, target_index.span_begin, last, options.fps, [&](double t, bool from_left) {
      return blend(index.clips, lookup.active_at(t, from_left), t, from_left).value;
    });
    out.curves[target] = thin_points(std::move(points), options.tolerance);
  }
  add_strongest_curve(index, 1, "viseme", out);
  add_strongest_curve(index, 2, "expression", out);
  return out;
}

Curves render_clip_curves(const Timeline& timeline, const CurveOptions& options) {
  Curves out;
  out.fps = options.fps;
  out.duration = timeline.end();
  // How many clips had each label so far: a macro used n times from one place must not look for
  // a free " #k" from 2 up each time (n^2 / 2 lookups).
  std::map<std::string, int> uses;
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
                        std::filesystem::path(clip.source.file).filename().string() + ":" +
                        std::to_string(clip.source.line) + ")";
    std::string unique = label;
    for (int& n = uses[label]; out.curves.contains(unique);) unique = label + " #" + std::to_string(++n + 1);
    out.curves[unique] = thin_points(std::move(points), options.tolerance);
  }
  return out;
}

}  // namespace fapc
