// The timing attributes of an FML story element (begin, duration or dur, end, repeat) as written,
// and their translation for the scheduler (docs/fml.md, "Timing": in a seq, begin and end count
// from the end of the previous element; end wins over duration).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "fapc/timeline/schedule.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::fml {

struct FmlTiming {
  std::optional<double> begin;
  std::optional<double> duration;  // duration or dur
  std::optional<double> end;
  std::optional<std::string> repeat;  // resolved by the reader: a count, indefinite or an event
};

// Errors at the attribute: a value that is not a time ("3", "3s", "250ms", "1.5min", "00:01.5"),
// a negative duration, an end not after the begin.
Result<FmlTiming> read_fml_timing(const xml::XmlDocument& doc, const xmlNode* element);

// The scheduler's timing of a time container.
Timing group_timing(const FmlTiming& timing);
// The scheduler's timing of a move: its simple duration is end - begin, else duration, else
// `intrinsic` (a talk's utterance, 1 s for the other moves).
Timing move_timing(const FmlTiming& timing, double intrinsic);

// The runs a tree would make (repeats of repeats, indefinite ones over `available` seconds), to
// check against max_runs before the scheduler makes them; `leaf_runs(leaf_id)` is what one run of
// a leaf makes. `shortest` is a lower bound of a node's active length, so that available / (one
// iteration) bounds an indefinite repeat's iterations. It counts the children's begin offsets,
// takes an end as given and is 0 for an indefinite repeat (an ancestor or a sibling's end may cut
// it anywhere). A lower bound of 0 means one iteration: its length is 0 (not repeated) or the
// whole limit. (An earlier estimate floored iterations at 1 ms and ignored offsets and ends:
// <seq repeat="indefinite"><par end="0.000001">... scheduled millions of runs;
// tests/fuzz/corpus/fml_reader/runs-*.fml.) Shared by the FML and SMIL-Agent readers.
double estimated_runs(const ScheduleNode& node, double available, double& shortest,
                      const std::function<double(std::size_t leaf_id)>& leaf_runs);

}  // namespace fapc::fml
