// Time-value lists (docs/timeline.md, "Rendering"): per target, the blended curve sampled at the
// frame rate plus every key-point time, jumps kept as two points at one time, then thinned.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <span>

#include "thin_points.hpp"
#include "timeline_index.hpp"

namespace fapc {
namespace {

using Points = std::vector<std::pair<double, double>>;

// The times where a clip's curve has a key point, an edge, or a jump, in absolute seconds, in
// order (so that the times of clips that do not overlap, taken in order, need no sort).
void add_clip_times(const Clip& clip, double end, std::vector<double>& times) {
  times.push_back(clip.begin);
  if (!clip.curve.periodic) {
    for (const KeyPoint& key : clip.curve.keys) {
      const double t = clip.begin + key.time - clip.curve_offset;
      if (t >= clip.begin && t <= end) times.push_back(t);
    }
  }
  if (std::isfinite(end)) times.push_back(end);
}

// Frames k, as [first, end).
using FrameRange = std::pair<std::int64_t, std::int64_t>;

// The frames k with from <= k / fps < to: k from ceil(from * fps) while k / fps < to.
FrameRange frame_range(double from, double to, int fps) {
  const auto first = static_cast<std::int64_t>(std::ceil(from * fps));
  const auto time = [fps](std::int64_t k) { return static_cast<double>(k) / fps; };
  // k / fps grows with k: start near the end and step to the first k at or past `to`.
  std::int64_t end = std::max(first, static_cast<std::int64_t>(std::ceil(to * fps)));
  while (end > first && time(end - 1) >= to) --end;
  while (time(end) < to) ++end;
  return {first, end};
}

void sort_unique(std::vector<double>& times) {
  if (!std::is_sorted(times.begin(), times.end())) std::sort(times.begin(), times.end());
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

// Calls visit(t) at each of `times` (sorted, no repeats) and at each frame time k / fps of the
// `frames` (ascending, apart), in time order, a time in both once: the frame times are merged in
// as they are counted rather than listed and sorted with the others.
template <class Visit>
void merge_times(const std::vector<double>& times, std::span<const FrameRange> frames, int fps, Visit visit) {
  std::size_t c = 0;
  for (const auto& [first, end] : frames) {
    for (std::int64_t k = first; k < end; ++k) {
      const double t = static_cast<double>(k) / fps;
      for (; c < times.size() && times[c] < t; ++c) visit(times[c]);
      if (c < times.size() && times[c] == t) ++c;
      visit(t);
    }
  }
  for (; c < times.size(); ++c) visit(times[c]);
}

// The samples thinned (in place: `samples` keeps its memory for the next list), as a list of its
// own size.
Points thinned(Points& samples, double tolerance) {
  thin_points(samples, tolerance);
  return Points(samples.begin(), samples.end());
}

// One target's blended value at ascending times: a cursor for each kind of query walks forward
// through its elementary intervals (TargetIndex::active_at) instead of a binary search per time,
// which, with the sort of every frame time, was most of the curves' cost on long scripts.
class ForwardLookup {
 public:
  ForwardLookup(const TimelineIndex& index, const TargetIndex& target) : index_(index), target_(target) {}
  // `t` may not go back between calls with the same `from_left`.
  double value_at(double t, bool from_left) {
    return blend(index_.clips, target_.active_at(t, from_left, from_left ? left_ : right_), t, from_left).value;
  }

 private:
  const TimelineIndex& index_;
  const TargetIndex& target_;
  std::size_t left_ = 0, right_ = 0;
};

// One target's (or clip's) curve at its clips' own times (`clip_times`, sorted, no repeats) and at
// every frame time from `from` to before `to`, in time order, each time once. Into `points`
// (emptied first).
template <class ValueFn>
void sample_merged(const std::vector<double>& clip_times, double from, double to, int fps, ValueFn value,
                   Points& points) {
  points.clear();
  const FrameRange frames = frame_range(from, to, fps);
  // Every time once, a jump twice: reserved at once, the points of a long target (tens of MB) are
  // never copied as the vector grows.
  const std::int64_t frame_count = std::max<std::int64_t>(frames.second - frames.first, 0);
  points.reserve(2 * clip_times.size() + static_cast<std::size_t>(frame_count) + 1);
  merge_times(clip_times, std::span<const FrameRange>(&frames, 1), fps,
              [&](double t) { add_sample(points, t, value); });
}

// docs/cli.md: FAP 1 and FAP 2 appear as "viseme" and "expression" curves whose value is the
// number of the strongest weight (0 when none), as for frame inputs; the weights themselves stay
// under their own targets. The number steps, so every change is a jump.
void add_strongest_curve(const TimelineIndex& index, int fap, const char* name, Curves& out, Points& points) {
  std::vector<std::pair<const TargetIndex*, double>> members;  // with the viseme/expression number
  std::vector<double> edges;                                   // the clips' begins and ends
  std::vector<FrameRange> frames;                              // each clip's
  for (const auto& [target, target_index] : index.targets) {
    const std::optional<WeightTarget> weight = weight_target(target);
    if (!weight || weight->fap != fap) continue;
    members.emplace_back(&target_index, weight->number);
    for (std::size_t i = 0; i < target_index.clips.size(); ++i) {
      const double begin = index.clips[target_index.clips[i]].begin;
      const double end = target_index.effective_end[i];
      edges.push_back(begin);
      if (std::isfinite(end)) edges.push_back(end);
      frames.push_back(frame_range(begin, std::min(end, out.duration), out.fps));
    }
  }
  if (members.empty()) return;
  sort_unique(edges);
  // The frames of all clips in order, each once: the clips' ranges merged (a sort of two numbers
  // per clip, not of every frame time of every clip).
  std::sort(frames.begin(), frames.end());
  std::vector<FrameRange> spans;
  for (const auto& range : frames) {
    if (range.first >= range.second) continue;
    if (!spans.empty() && range.first <= spans.back().second) {
      spans.back().second = std::max(spans.back().second, range.second);
    } else {
      spans.push_back(range);
    }
  }
  std::vector<FrameRange>().swap(frames);
  std::vector<ForwardLookup> lookups;
  for (const auto& member : members) lookups.emplace_back(index, *member.first);
  const auto strongest = [&](double t, bool from_left) {
    double best = 0;
    double slot = 0;
    for (std::size_t m = 0; m < members.size(); ++m) {
      const double number = members[m].second;
      const double w = lookups[m].value_at(t, from_left);
      if (w > best) {
        best = w;
        slot = number;
      }
    }
    return slot;
  };
  points.clear();
  const auto add = [&](double t) {
    const double now = strongest(t, false);
    if (!points.empty() && points.back().second != now) points.emplace_back(t, points.back().second);
    points.emplace_back(t, now);
  };
  merge_times(edges, spans, out.fps, add);
  out.curves[name] = thinned(points, 0);
}

}  // namespace

Curves render_curves(const Timeline& timeline, const CurveOptions& options) {
  const TimelineIndex index(timeline.clips);
  Curves out;
  out.fps = options.fps;
  out.duration = timeline.end();
  Points samples;  // one target's at a time: the memory of the longest is touched once
  for (const auto& [target, target_index] : index.targets) {
    std::vector<double> times;
    for (std::size_t i = 0; i < target_index.clips.size(); ++i) {
      const double end = std::min(target_index.effective_end[i], out.duration);
      add_clip_times(index.clips[target_index.clips[i]], end, times);
    }
    const double last = std::min(target_index.span_end, out.duration);
    times.push_back(last);
    sort_unique(times);
    ForwardLookup lookup(index, target_index);
    sample_merged(
        times, target_index.span_begin, last, options.fps,
        [&](double t, bool from_left) { return lookup.value_at(t, from_left); }, samples);
    out.curves[target] = thinned(samples, options.tolerance);
  }
  add_strongest_curve(index, 1, "viseme", out, samples);
  add_strongest_curve(index, 2, "expression", out, samples);
  return out;
}

Curves render_clip_curves(const Timeline& timeline, const CurveOptions& options) {
  Curves out;
  out.fps = options.fps;
  out.duration = timeline.end();
  // How many clips had each label so far: a macro used n times from one place must not look for
  // a free " #k" from 2 up each time (n^2 / 2 lookups).
  std::map<std::string, int> uses;
  Points samples;
  for (const Clip& clip : timeline.clips) {
    std::vector<double> times;
    add_clip_times(clip, clip.end, times);
    sort_unique(times);
    sample_merged(
        times, clip.begin, clip.end, options.fps,
        [&](double t, bool from_left) {
          return t >= clip.end && !from_left ? clip_value(clip, t, true) : clip_value(clip, t, from_left);
        },
        samples);
    // "jaw (table2.mimic:5)"; a second clip from the same place (a macro used twice) gets " #2".
    std::string label = clip.target + " (" + std::filesystem::path(clip.source.file.str()).filename().string() + ":" +
                        std::to_string(clip.source.line) + ")";
    std::string unique = label;
    for (int& n = uses[label]; out.curves.contains(unique);) unique = label + " #" + std::to_string(++n + 1);
    out.curves[unique] = thinned(samples, options.tolerance);
  }
  return out;
}

}  // namespace fapc
