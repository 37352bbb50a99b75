// What the SMIL-Agent reader builds before scheduling (smil_reader.cpp): the time tree for
// fapc::timeline::schedule_tree() and, per leaf, what it says. place_behaviours() turns the scheduled runs
// into a BML block (bml/bml_model.hpp) whose lowering is the BML reader's.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bml/bml_model.hpp"
#include "bml/speak_text.hpp"
#include "fapc/smil/smil.hpp"
#include "fapc/timeline/schedule.hpp"

namespace fapc::smil {

struct SmilLeaf {
  enum class Kind : std::uint8_t { speech, affect, action };
  Kind kind = Kind::speech;
  Location where;
  std::string name;  // the affect, or the action's type and parameters; the speech's id
  // Affects and actions: the behaviours one run draws (their timing set when placed). Empty when
  // fapc does not know the affect or action (it was warned about; its span is kept).
  std::vector<bml::Behaviour> behaviours;
  bool shift = false;  // fill="freeze": the display holds after its span
  // Anchored to a speech (content-id): its span runs from content-begin (the speech's start) to
  // content-end (its end), `offset` seconds later; `duration` (dur) replaces a missing content-end.
  // A speech's `duration`: its dur or end when given (it is placed by them; its voice is not cut).
  std::optional<std::size_t> speech;  // leaf index of the speech
  std::optional<std::size_t> begin_mark;
  std::optional<std::size_t> end_mark;
  double offset = 0;
  std::optional<double> duration;
  // Speech: what it says (marks at their text offsets) and in which language, or a recording.
  bml::MarkedText text;
  std::string language;
  std::unique_ptr<bml::SpokenText> spoken;
};

// A scheduled script, ready to lower.
struct PlacedScript {
  bml::Block block;
  bml::Solution solution;
  double end = 0;
  Location end_source;
};

// The runs of `schedule` as behaviours of one block: a speech per run of a speech leaf, an
// affect's or action's behaviours per run of its own (unanchored) or per run of its speech
// (anchored), each fitted to its span by the BML defaults' onset and offset. `placed` gets one
// entry per affect or action span. Errors: an anchored span that ends before it starts, more
// spans than `max_runs`.
Result<PlacedScript> place_behaviours(const std::vector<SmilLeaf>& leaves, const Schedule& schedule,
                                      std::int64_t max_runs, std::vector<PlacedBehaviour>& placed);

}  // namespace fapc::smil
