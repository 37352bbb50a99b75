// Blending (docs/timeline.md, "Blending"). Per target, the clips' begins and (fill-resolved) ends
// cut time into elementary intervals, each with the list of clips active in it, so a query is one
// binary search plus the blend of the few clips active there.
#include "timeline_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>

namespace fapc {
namespace {

constexpr double kForever = std::numeric_limits<double>::infinity();

}  // namespace

TargetIndex::TargetIndex(const std::vector<Clip>& all, std::vector<std::uint32_t> of_target)
    : clips(std::move(of_target)) {
  // By begin, ties in source order. The begins are copied beside the indices first: a target's
  // clips lie scattered among the others', and comparing through the indices would miss the cache
  // at every step on a long timeline. They mostly come in order already.
  std::vector<double> begins(clips.size());
  for (std::size_t i = 0; i < clips.size(); ++i) begins[i] = all[clips[i]].begin;
  if (!std::is_sorted(begins.begin(), begins.end())) {
    std::vector<std::pair<double, std::uint32_t>> by_begin(clips.size());
    for (std::size_t i = 0; i < clips.size(); ++i) by_begin[i] = {begins[i], clips[i]};
    std::sort(by_begin.begin(), by_begin.end());  // the indices ascend: ties stay in source order
    for (std::size_t i = 0; i < clips.size(); ++i) std::tie(begins[i], clips[i]) = by_begin[i];
  }
  // A frozen clip holds until the next clip of its target that begins at or after its end.
  effective_end.reserve(clips.size());
  for (const std::uint32_t c : clips) {
    const Clip& clip = all[c];
    double end = clip.end;
    if (clip.fill == Fill::freeze) {
      const auto next = std::lower_bound(begins.begin(), begins.end(), clip.end);
      end = next == begins.end() ? kForever : std::max(clip.end, *next);
    }
    effective_end.push_back(end);
  }
  build_intervals(begins);
}

void TargetIndex::build_intervals(const std::vector<double>& begins) {
  // The clips' starts come in the order of `clips` (by begin), their ends in the order of
  // `by_end` (the same order unless clips overlap): the two are merged as they are walked, so that
  // nothing but 4 bytes a clip is held besides the result. The order within one time does not
  // matter: all its starts and ends are taken before the interval after it is recorded, and no
  // clip both starts and ends at one time. Empty clips never count.
  const auto counts = [&](std::size_t i) { return effective_end[i] > begins[i]; };
  std::vector<std::uint32_t> by_end;  // positions in `clips`
  by_end.reserve(clips.size());
  for (std::size_t i = 0; i < clips.size(); ++i)
    if (counts(i)) by_end.push_back(static_cast<std::uint32_t>(i));
  const auto ends_before = [&](std::uint32_t a, std::uint32_t b) { return effective_end[a] < effective_end[b]; };
  if (!std::is_sorted(by_end.begin(), by_end.end(), ends_before)) std::sort(by_end.begin(), by_end.end(), ends_before);
  // The clips active, in source order (which blending needs): a sorted vector, as a target has
  // few clips active at once.
  std::vector<std::uint32_t> active;
  offsets.push_back(0);
  std::size_t start = 0, end = 0;  // the next start (in `clips`) and end (in `by_end`)
  const auto skip_empty = [&] {
    while (start < clips.size() && !counts(start)) ++start;
  };
  for (skip_empty(); start < clips.size() || end < by_end.size();) {
    const double time = std::min(start < clips.size() ? begins[start] : kForever,
                                 end < by_end.size() ? effective_end[by_end[end]] : kForever);
    for (; start < clips.size() && begins[start] == time; ++start, skip_empty())
      active.insert(std::lower_bound(active.begin(), active.end(), clips[start]), clips[start]);
    for (; end < by_end.size() && effective_end[by_end[end]] == time; ++end)
      active.erase(std::lower_bound(active.begin(), active.end(), clips[by_end[end]]));
    cuts.push_back(time);
    members.insert(members.end(), active.begin(), active.end());
    offsets.push_back(static_cast<std::uint32_t>(members.size()));
  }
  if (!cuts.empty()) {
    span_begin = cuts.front();
    span_end = cuts.back();
  }
}

std::span<const std::uint32_t> TargetIndex::active_at(double t, bool from_left) const {
  // Interval j is [cuts[j], cuts[j+1]) (from the left: (cuts[j], cuts[j+1]]).
  const auto it =
      from_left ? std::lower_bound(cuts.begin(), cuts.end(), t) : std::upper_bound(cuts.begin(), cuts.end(), t);
  if (it == cuts.begin()) return {};
  const auto j = static_cast<std::size_t>(it - cuts.begin() - 1);
  return std::span<const std::uint32_t>(members).subspan(offsets[j], offsets[j + 1] - offsets[j]);
}

double clip_value(const Clip& clip, double t, bool from_left) {
  // Past its end a (frozen) clip holds the value it reached, the limit from the left.
  if (t >= clip.end) return clip.curve.left_limit(clip.local_time(clip.end));
  const double local = clip.local_time(t);
  return from_left ? clip.curve.left_limit(local) : clip.curve.value_at(local);
}

Blended blend(const std::vector<Clip>& all, std::span<const std::uint32_t> active, double t, bool from_left) {
  Blended result;
  if (active.empty()) return result;
  // 1. The overwrite clip that began last wins (ties: the later in the source).
  const Clip* winner = nullptr;
  bool any_average = false;
  for (const std::uint32_t c : active) {
    const Clip& clip = all[c];
    if (clip.blend == BlendMode::overwrite && (!winner || clip.begin >= winner->begin)) {
      winner = &clip;
      result.cause = c;
    }
    any_average = any_average || clip.blend == BlendMode::average;
  }
  if (winner) {
    result.value = clip_value(*winner, t, from_left);
    return result;
  }
  // 2. Any average: the mean of all; 3. otherwise the sum. The cause is the largest contributor.
  double largest = -1;
  for (const std::uint32_t c : active) {
    const double v = clip_value(all[c], t, from_left);
    result.value += v;
    if (std::abs(v) > largest) {
      largest = std::abs(v);
      result.cause = c;
    }
  }
  if (any_average) result.value /= static_cast<double>(active.size());
  return result;
}

TimelineIndex::TimelineIndex(const std::vector<Clip>& timeline_clips) : clips(timeline_clips) {
  // Interned names: equal targets are one string, so the clips group by its address (a hash of a
  // pointer, not a comparison of names per clip); the map then orders the few targets by name.
  std::unordered_map<const std::string*, std::vector<std::uint32_t>> by_target;
  const std::string* last = nullptr;
  std::vector<std::uint32_t>* last_list = nullptr;
  for (std::size_t i = 0; i < clips.size(); ++i) {
    const std::string* name = &clips[i].target.str();
    if (name != last) {
      last = name;
      last_list = &by_target[name];
    }
    last_list->push_back(static_cast<std::uint32_t>(i));
  }
  for (auto& [target, list] : by_target) {
    targets.emplace(*target, TargetIndex(clips, std::move(list)));
  }
}

Blended TimelineIndex::value_at(const TargetIndex& target, double t, bool from_left) const {
  return blend(clips, target.active_at(t, from_left), t, from_left);
}

Blended TimelineIndex::value_at(const TargetIndex& target, double t, bool from_left, std::size_t& cursor) const {
  return blend(clips, target.active_at(t, from_left, cursor), t, from_left);
}

// ---- the public face -----------------------------------------------------------------------

// The evaluator may outlive the timeline it was built from, so it keeps its own clips.
struct TimelineEvaluator::Impl {
  explicit Impl(const Timeline& timeline) : clips(timeline.clips), index(clips) {}
  Impl(const Impl&) = delete;
  std::vector<Clip> clips;
  TimelineIndex index;
};

TimelineEvaluator::TimelineEvaluator(const Timeline& timeline) : impl_(std::make_shared<const Impl>(timeline)) {}

std::vector<std::string> TimelineEvaluator::targets() const {
  std::vector<std::string> names;
  for (const auto& [name, index] : impl_->index.targets) names.push_back(name);
  return names;
}

double TimelineEvaluator::value_at(const std::string& target, double t, bool from_left) const {
  const auto found = impl_->index.targets.find(target);
  if (found == impl_->index.targets.end()) return 0;
  return impl_->index.value_at(found->second, t, from_left).value;
}

std::pair<double, double> TimelineEvaluator::span(const std::string& target) const {
  const auto found = impl_->index.targets.find(target);
  if (found == impl_->index.targets.end()) return {0, 0};
  return {found->second.span_begin, found->second.span_end};
}

}  // namespace fapc
