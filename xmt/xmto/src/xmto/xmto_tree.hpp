// What the XMT-Omega reader builds before scheduling: the time tree for fapc::timeline::schedule() and, per
// leaf, what its runs become on the timeline. lower_to_timeline() turns the scheduled runs into
// clips (docs/xmt-omega.md).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fapc/timeline/schedule.hpp"
#include "fapc/timeline/timeline.hpp"
#include "xmto/animation_function.hpp"

namespace fapc::xmto {

struct Leaf {
  Location where;
  // animate/set: the clips' fill. animation: freeze freezes every included clip; remove keeps
  // each included clip's own fill.
  Fill fill = Fill::remove;
  // animate and set: the target (in XmtoTree::targets) and the function, its values at
  // XmtoTree::numbers[first_number ..] followed by its key times.
  std::uint32_t target = 0;
  std::uint32_t first_number = 0;
  std::uint32_t value_count = 0;
  std::uint32_t key_time_count = 0;
  AnimationShape function;
  // animation src: the included input's timeline, starting at 0 (a pointer: most leaves have none).
  std::unique_ptr<Timeline> included;
};

// A leaf is a few dozen bytes: names and numbers are kept once for the whole tree.
struct XmtoTree {
  ScheduleNode root;
  std::vector<Leaf> leaves;  // indexed by ScheduleNode::leaf_id, in document order
  std::vector<std::string> targets;
  std::vector<double> numbers;

  std::span<const double> values(const Leaf& leaf) const {
    return {numbers.data() + leaf.first_number, leaf.value_count};
  }
  std::span<const double> key_times(const Leaf& leaf) const {
    return {numbers.data() + leaf.first_number + leaf.value_count, leaf.key_time_count};
  }
  const std::string& target(const Leaf& leaf) const { return targets[leaf.target]; }
};

// Clips in document order of their elements (ties between overwrite clips go to the later
// element), each run of a leaf one clip (an included animation: its clips shifted).
Timeline lower_to_timeline(const XmtoTree& tree, const Schedule& schedule);
// Where the body ends (the end_source of lower_to_timeline's timeline), known before lowering:
// for errors about the body's length.
Location body_end_source(const XmtoTree& tree, const Schedule& schedule);

}  // namespace fapc::xmto
