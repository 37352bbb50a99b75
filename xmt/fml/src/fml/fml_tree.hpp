// What the FML reader builds before scheduling: the time tree for fapc::timeline::schedule() and, per leaf,
// what its runs become on the timeline. lower_fml() turns the scheduled runs into clips.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fapc/timeline/schedule.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fml/speech_visemes.hpp"

namespace fapc::fml {

// What a talk says: its visemes and, when spoken, its voice.
struct FmlTalk {
  Speech speech;
  AudioClip audio;     // the voice of a spoken talk (no samples: a silent one, stretched to its runs)
  double natural = 0;  // a talk's own length: its speech, or the last viseme's fade to neutral if later
};

// A few dozen bytes per move: the target's name is kept once in the tree, a talk's speech apart.
struct FmlLeaf {
  enum class Kind : std::uint8_t {
    move,    // expr, hdmv, fap, param: `target` ramps from its current value to `value`
    normal,  // expr type="normal": every expression placed before ramps to 0
    talk,    // `talk` (its audio when spoken): see lower_fml
    wait,    // nothing
  };
  Kind kind = Kind::wait;
  std::uint32_t target = 0;  // in FmlTree::targets
  double value = 0;
  Location where;
  std::unique_ptr<FmlTalk> talk;
};

struct FmlTree {
  ScheduleNode root;
  std::vector<FmlLeaf> leaves;  // indexed by ScheduleNode::leaf_id, in document order
  std::vector<std::string> targets;
  Coarticulation coarticulation;
};

// Move runs are placed in order of their begin (document order on ties), each starting from the
// value its target has just before: the latest placed clip of that target, frozen at its end.
// A talk's visemes overlap by the coarticulation rule; a spoken talk keeps its own length (its
// audio and visemes cut at the run's end), a silent one is stretched to the run.
Timeline lower_fml(const FmlTree& tree, const Schedule& schedule);
// Where the story ends (the end_source of lower_fml's timeline), known before lowering: for
// errors about the story's length.
Location story_end_source(const FmlTree& tree, const Schedule& schedule);

}  // namespace fapc::fml
