// Private: the per-target index behind TimelineEvaluator, render_frames and render_curves.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "fapc/transcoder/render.hpp"

namespace fapc {

struct TargetIndex {
  TargetIndex(const std::vector<Clip>& all, std::vector<std::uint32_t> of_target);

  std::vector<std::uint32_t> clips;   // indices into the timeline, by begin
  std::vector<double> effective_end;  // per entry of `clips`, fill=freeze resolved
  // Elementary interval j is [cuts[j], cuts[j+1]); its active clips are
  // members[offsets[j] .. offsets[j+1]), in source order.
  std::vector<double> cuts;
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> members;
  double span_begin = 0;  // first begin .. last effective end (may be infinite)
  double span_end = 0;

  std::span<const std::uint32_t> active_at(double t, bool from_left) const;
  // The same, starting from the interval `cursor` names (updated): a walk of a step or two when
  // times ascend, as frames and curve samples do, instead of a binary search. A cursor serves one
  // kind of query (from the left or not).
  std::span<const std::uint32_t> active_at(double t, bool from_left, std::size_t& cursor) const;

 private:
  void build_intervals(const std::vector<double>& begins);  // of `clips`
};

// Inline: the renderers ask it for every frame of every target.
inline std::span<const std::uint32_t> TargetIndex::active_at(double t, bool from_left, std::size_t& cursor) const {
  // Interval j is [cuts[j], cuts[j+1]) (from the left: (cuts[j], cuts[j+1]]): the last j whose cut
  // t has passed; before the first cut nothing is active. A cursor that lies ahead of t, or far
  // behind it, gives way to the binary search.
  constexpr std::size_t kWalk = 4;
  const auto passed = [&](double cut) { return from_left ? cut < t : cut <= t; };
  std::size_t j = cursor;
  if (j >= cuts.size() || !passed(cuts[j])) return active_at(t, from_left);
  for (std::size_t steps = 0; j + 1 < cuts.size() && passed(cuts[j + 1]); ++j, ++steps)
    if (steps == kWalk) {
      const auto from = cuts.begin() + static_cast<std::ptrdiff_t>(j);
      const auto it = from_left ? std::lower_bound(from, cuts.end(), t) : std::upper_bound(from, cuts.end(), t);
      j = static_cast<std::size_t>(it - cuts.begin() - 1);
      break;
    }
  cursor = j;
  return std::span<const std::uint32_t>(members).subspan(offsets[j], offsets[j + 1] - offsets[j]);
}

struct Blended {
  double value = 0;
  std::int64_t cause = -1;  // the clip that decided the value (for warnings), -1 when none
};

// The value of one clip at absolute time t (a frozen clip past its end keeps its end value);
// `from_left`: the limit from the left, which is what a clip has at its own end.
double clip_value(const Clip& clip, double t, bool from_left = false);
Blended blend(const std::vector<Clip>& all, std::span<const std::uint32_t> active, double t, bool from_left);

// Refers to the timeline's clips (no copy: a clip may hold long curves): the timeline must outlive it.
struct TimelineIndex {
  explicit TimelineIndex(const std::vector<Clip>& timeline_clips);

  const std::vector<Clip>& clips;
  std::map<std::string, TargetIndex> targets;

  Blended value_at(const TargetIndex& target, double t, bool from_left) const;
  Blended value_at(const TargetIndex& target, double t, bool from_left, std::size_t& cursor) const;
};

}  // namespace fapc
