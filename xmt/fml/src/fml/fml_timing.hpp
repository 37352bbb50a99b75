// The timing attributes of an FML story element (begin, duration or dur, end, repeat) as written,
// and their translation for the scheduler (docs/fml.md, "Timing": in a seq, begin and end count
// from the end of the previous element; end wins over duration).
#pragma once

#include <optional>
#include <string>

#include "fapc/transcoder/schedule.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::xmt {

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

}  // namespace fapc::xmt
