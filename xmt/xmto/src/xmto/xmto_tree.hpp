// What the XMT-Omega reader builds before scheduling: the time tree for fapc::schedule() and, per
// leaf, what its runs become on the timeline. lower_to_timeline() turns the scheduled runs into
// clips (docs/xmt-omega.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fapc/transcoder/schedule.hpp"
#include "fapc/transcoder/timeline.hpp"
#include "xmto/animation_function.hpp"

namespace fapc::xmt {

struct Leaf {
  Location where;
  // animate/set: the clips' fill. animation: freeze freezes every included clip; remove keeps
  // each included clip's own fill.
  Fill fill = Fill::remove;
  // animate and set:
  std::string target;
  AnimationFunction function;
  // animation src: the included input's timeline, starting at 0 (a pointer: most leaves have none).
  std::unique_ptr<Timeline> included;
};

struct XmtoTree {
  ScheduleNode root;
  std::vector<Leaf> leaves;  // indexed by ScheduleNode::leaf_id, in document order
};

// Clips in document order of their elements (ties between overwrite clips go to the later
// element), each run of a leaf one clip (an included animation: its clips shifted).
Timeline lower_to_timeline(const XmtoTree& tree, const Schedule& schedule);

}  // namespace fapc::xmt
