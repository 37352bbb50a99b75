// The SMIL timing attributes of one XMT-Omega element (begin, dur, end, repeatCount, repeatDur,
// fill) as written, and their translation into the scheduler's Timing by SMIL 2.0's rules for the
// active duration (docs/xmt-omega.md, "Timing").
#pragma once

#include <optional>

#include "fapc/timeline/schedule.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::xmto {

struct SmilTiming {
  std::optional<double> begin;    // signed offset; empty: no begin attribute
  bool begin_indefinite = false;  // begin="indefinite": waits for an event that never comes
  std::optional<double> dur;      // a clock value (> 0)
  bool dur_indefinite = false;    // dur="indefinite"
  std::optional<double> end;      // signed offset, measured like begin
  std::optional<double> repeat_count;
  bool repeat_count_indefinite = false;
  std::optional<double> repeat_dur;
  bool repeat_dur_indefinite = false;
  std::optional<Fill> fill;  // empty: inherit from the enclosing element
  bool fill_auto = false;    // fill="auto": freeze when no dur, end or repeat is given

  bool has_begin() const { return begin || begin_indefinite; }
  // Any of dur, repeatCount, repeatDur: with one of them, `end` only shortens (SMIL's min rule).
  bool has_duration_attribute() const {
    return dur || dur_indefinite || repeat_count || repeat_count_indefinite || repeat_dur || repeat_dur_indefinite;
  }
  // An end at or before the begin: SMIL creates no interval, the element never plays.
  bool never_plays() const { return end && *end <= begin.value_or(0); }
  // The fill the element's own attributes say, or `inherited`.
  Fill effective_fill(Fill inherited) const;
};

// Reads the attributes; errors at the attribute (malformed values, event-based or list timing,
// which this reader does not support).
Result<SmilTiming> read_smil_timing(const xml::XmlDocument& doc, const xmlNode* element);

// The scheduler's timing. `implicit` is the simple duration the element has when `dur` is absent
// (an included animation's length); empty for animate, set and the time containers.
Timing to_schedule_timing(const SmilTiming& smil, std::optional<double> implicit);

}  // namespace fapc::xmto
