// GrowingTimeline (growing_timeline.hpp). Per target, the planned clips sit in slots sorted by
// begin; a max-tree over the slots holds each added clip's effective end (fill=freeze resolved
// against the clips added so far) and -infinity for slots not added yet. The clips active at t are
// the slots with begin <= t whose effective end is above t: a descent that skips every subtree
// whose largest end is not.
#include "fapc/transcoder/growing_timeline.hpp"

#include <algorithm>
#include <limits>

#include "timeline_index.hpp"

namespace fapc {
namespace {

constexpr double kAbsent = -std::numeric_limits<double>::infinity();
constexpr double kForever = std::numeric_limits<double>::infinity();

}  // namespace

struct GrowingTimeline::Target {
  std::vector<double> begins;        // per slot, ascending
  std::vector<std::uint32_t> added;  // per slot: the clip's index in clips_ once added
  std::vector<double> tree;          // max-tree over the slots' effective ends, leaves at [leaves, 2 leaves)
  std::size_t leaves = 1;
  std::multimap<double, std::uint32_t> frozen_by_end;  // added fill=freeze clips: end -> slot

  void init() {
    while (leaves < begins.size()) leaves *= 2;
    tree.assign(2 * leaves, kAbsent);
    added.assign(begins.size(), 0);
  }
  void set(std::size_t slot, double effective_end) {
    std::size_t node = leaves + slot;
    tree[node] = effective_end;
    for (node /= 2; node >= 1; node /= 2) tree[node] = std::max(tree[2 * node], tree[2 * node + 1]);
  }
  // Slots below `end` whose effective end is above t, appended to `out`.
  void collect(std::size_t node, std::size_t lo, std::size_t hi, std::size_t end, double t,
               std::vector<std::uint32_t>& out) const {
    if (lo >= end || !(tree[node] > t)) return;
    if (hi - lo == 1) {
      out.push_back(added[lo]);
      return;
    }
    const std::size_t mid = (lo + hi) / 2;
    collect(2 * node, lo, mid, end, t, out);
    collect(2 * node + 1, mid, hi, end, t, out);
  }
  // The last added slot below `end`, or -1.
  std::int64_t last_added_below(std::size_t node, std::size_t lo, std::size_t hi, std::size_t end) const {
    if (lo >= end || tree[node] == kAbsent) return -1;
    if (hi - lo == 1) return static_cast<std::int64_t>(lo);
    const std::size_t mid = (lo + hi) / 2;
    const std::int64_t right = last_added_below(2 * node + 1, mid, hi, end);
    return right >= 0 ? right : last_added_below(2 * node, lo, mid, end);
  }
  // The first added slot at or after `from`, or -1.
  std::int64_t first_added_from(std::size_t node, std::size_t lo, std::size_t hi, std::size_t from) const {
    if (hi <= from || tree[node] == kAbsent) return -1;
    if (hi - lo == 1) return static_cast<std::int64_t>(lo);
    const std::size_t mid = (lo + hi) / 2;
    const std::int64_t left = first_added_from(2 * node, lo, mid, from);
    return left >= 0 ? left : first_added_from(2 * node + 1, mid, hi, from);
  }
  std::size_t slots_beginning_by(double t) const {  // slots with begin <= t
    return static_cast<std::size_t>(std::upper_bound(begins.begin(), begins.end(), t) - begins.begin());
  }
};

GrowingTimeline::GrowingTimeline(const std::vector<PlannedClip>& planned, const std::vector<Clip>& clips)
    : clips_(&clips) {
  // Slots by begin within each target; ties keep the planned order (it does not matter: only
  // begins and effective ends are compared, and blending follows the add order).
  std::vector<std::uint32_t> order(planned.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return planned[a].begin < planned[b].begin; });
  where_.resize(planned.size());
  for (const std::uint32_t i : order) {
    std::unique_ptr<Target>& target = targets_[planned[i].target];
    if (!target) target = std::make_unique<Target>();
    where_[i] = {target.get(), static_cast<std::uint32_t>(target->begins.size())};
    target->begins.push_back(planned[i].begin);
  }
  for (auto& [name, target] : targets_) target->init();
}

GrowingTimeline::~GrowingTimeline() = default;
GrowingTimeline::GrowingTimeline(GrowingTimeline&&) noexcept = default;
GrowingTimeline& GrowingTimeline::operator=(GrowingTimeline&&) noexcept = default;

void GrowingTimeline::add(std::size_t planned_index, std::size_t clip_index) {
  const Clip& clip = (*clips_)[clip_index];
  Target& target = *where_[planned_index].first;
  const std::uint32_t slot = where_[planned_index].second;
  const double begin = target.begins[slot];
  // A frozen clip holds until the next clip of its target that begins at or after its end: the
  // new begin cuts those whose end lies after every begin added so far that is <= it.
  const std::int64_t before = target.last_added_below(1, 0, target.leaves, target.slots_beginning_by(begin));
  const double previous_begin = before >= 0 ? target.begins[static_cast<std::size_t>(before)] : kAbsent;
  for (auto it = target.frozen_by_end.upper_bound(previous_begin);
       it != target.frozen_by_end.end() && it->first <= begin; ++it) {
    target.set(it->second, begin);
  }
  double effective_end = clip.end;
  if (clip.fill == Fill::freeze) {
    const auto from = static_cast<std::size_t>(std::lower_bound(target.begins.begin(), target.begins.end(), clip.end) -
                                               target.begins.begin());
    const std::int64_t next = target.first_added_from(1, 0, target.leaves, from);
    effective_end = next >= 0 ? std::max(clip.end, target.begins[static_cast<std::size_t>(next)]) : kForever;
    target.frozen_by_end.emplace(clip.end, slot);
  }
  // An empty clip (effective end <= begin) is never found active, yet cuts frozen clips.
  target.set(slot, effective_end);
  target.added[slot] = static_cast<std::uint32_t>(clip_index);
}

double GrowingTimeline::value_at(const std::string& name, double t) const {
  const auto found = targets_.find(name);
  if (found == targets_.end()) return 0;
  const Target& target = *found->second;
  std::vector<std::uint32_t> active;
  target.collect(1, 0, target.leaves, target.slots_beginning_by(t), t, active);
  std::sort(active.begin(), active.end());  // add order, which blending follows
  return blend(*clips_, active, t, false).value;
}

}  // namespace fapc
