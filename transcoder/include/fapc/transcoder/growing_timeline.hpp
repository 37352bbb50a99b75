// Blended values on a timeline that receives its clips one at a time: what XMT-Omega
// to-animations need, each starting from the value its target has, without it, when a run
// begins (docs/xmt-omega.md), while the to-animations placed before it count.
//
// Building a TimelineEvaluator per to-animation over every clip of its target costs the square
// of the document. Here every clip's place (target, begin, end, fill) is known up front, so each
// target keeps its clips in one array sorted by begin, with a max-tree over their effective ends;
// adding a clip and asking a value cost O(log n) plus the clips active at that time (and the
// frozen clips the new one cuts short). The values are those a TimelineEvaluator built over the
// clips added so far would give (docs/timeline.md, "Blending"), in the order they were added.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fapc/timeline/timeline.hpp"

namespace fapc {

// A clip that will be added: its target and begin are all the plan needs.
struct PlannedClip {
  TargetName target;
  double begin = 0;
};

class GrowingTimeline {
 public:
  // Every clip that will be added; add() later names them by their index here. Only targets in
  // this list can be asked about. The added clips stay in the caller's `clips` (read, not copied:
  // the list may grow between calls, but a clip once added must keep its place and its value).
  GrowingTimeline(const std::vector<PlannedClip>& planned, const std::vector<Clip>& clips);
  ~GrowingTimeline();
  GrowingTimeline(GrowingTimeline&&) noexcept;
  GrowingTimeline& operator=(GrowingTimeline&&) noexcept;

  // Adds planned clip `planned_index`, which is clips[clip_index] with its final curve. Clips are
  // added in the order of their indices in `clips`, the timeline's order: overwrite ties between
  // clips that begin together go to the one added later.
  void add(std::size_t planned_index, std::size_t clip_index);
  // The blended value of `target` at t over the clips added so far; 0 where none is active.
  double value_at(const std::string& target, double t) const;

 private:
  struct Target;
  const std::vector<Clip>* clips_;
  std::vector<std::pair<Target*, std::uint32_t>> where_;  // per planned clip: its target, its slot
  std::map<std::string, std::unique_ptr<Target>> targets_;
};

}  // namespace fapc
