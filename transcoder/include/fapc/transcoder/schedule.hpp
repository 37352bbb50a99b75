// The one scheduler of the project (docs/timeline.md): resolves a tree of sequences, parallels and
// exclusive groups into absolute intervals for its leaves. Every front end (Mimic, FML, XMT-Omega)
// builds a ScheduleNode tree from its source, calls schedule(), and makes clips from the
// occurrences. It knows timing only, nothing about curves.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc {

// Timing of one node. All times in seconds. Which field a front end fills:
//   Mimic  left=x -> offset; right=x -> align_right; periodic duration -> duration.
//   SMIL/FML/XMT-Omega begin -> offset; dur -> duration; end -> end; repeatCount/repeat -> repeat;
//   repeatDur -> repeat_duration.
struct Timing {
  // Shift from the default start: in a sequence the end of the previous child, in a parallel or
  // exclusive group the group's start.
  double offset = 0;
  // The simple duration. Leaves: intrinsic (e.g. a fade's in+hold+out) or given; empty means
  // "until the parent's reference end" (a Mimic periodic without duration, SMIL indefinite).
  // Groups: empty means "from the children".
  std::optional<double> duration;
  // The end, measured like offset from the default start; wins over duration (the active
  // duration becomes end - offset).
  std::optional<double> end;
  // Only in parallels: end at the parallel's reference end + x (the start moves, the duration
  // stays). Mimic's `right` / `right=x`.
  std::optional<double> align_right;
  double repeat = 1;               // iterations, may be fractional (SMIL repeatCount)
  bool repeat_indefinite = false;  // until the parent's end; an error when there is none
  std::optional<double> repeat_duration;  // caps the active duration (SMIL repeatDur)
};

struct ScheduleNode {
  enum class Kind { leaf, sequence, parallel, exclusive };
  Kind kind = Kind::leaf;
  Timing timing;
  std::vector<ScheduleNode> children;
  std::size_t leaf_id = 0;  // leaves: the front end's own index, returned in Occurrence
  Location source;          // for errors
  // Any node: the front end's own identity for it (an index into its element table, say),
  // returned in ScheduleError so that the front end names the element without parsing text.
  std::size_t tag = 0;

  static ScheduleNode leaf(std::size_t id, Timing timing, Location source);
  static ScheduleNode group(Kind kind, Timing timing, Location source);
};

// One run of a leaf. A repeated leaf (or a leaf inside a repeated group) runs several times.
struct Occurrence {
  std::size_t leaf_id = 0;
  double begin = 0;            // absolute start of this run's simple duration
  double simple_duration = 0;  // the curve's length
  double end = 0;              // absolute active end: begin + simple_duration, or earlier when an
                               // ancestor ends first or the run is the cut last repeat
  double curve_offset = 0;     // local time at `begin` (0 unless the run's start was cut)
  int iteration = 0;           // 0-based repeat index of the leaf itself
};

struct ScheduleOptions {
  // The root's end when the source gives none (--duration): lets indefinite repeats and periodic
  // leaves without duration at the top level end.
  std::optional<double> root_end;
  // The most runs (occurrences) a schedule may have; more is an error at the node that repeats.
  std::size_t max_runs = 2000000;
};

struct Schedule {
  std::vector<Occurrence> occurrences;  // in tree order (depth first), then by iteration
  double end = 0;                       // the root's active end
};

// Why a tree cannot be scheduled, as a value: front ends decide by `problem` and name the
// element by `node_tag`, never by the wording.
enum class ScheduleProblem {
  no_duration,          // a leaf with no duration and nothing around it ends
  endless_repeat,       // a group repeats indefinitely and nothing around it ends
  starts_before_zero,   // a leaf would start before time 0
  right_without_end,    // aligned right in a parallel whose end is unknown
  right_in_sequence,    // aligned right outside a parallel
  too_many_runs,        // more than ScheduleOptions::max_runs runs
};

struct ScheduleError {
  ScheduleProblem problem = ScheduleProblem::no_duration;
  std::size_t node_tag = 0;  // the failing node's ScheduleNode::tag
  Location where;            // the failing node's source
  // What is wrong, without a subject: "has no duration and nothing around it ends: ...".
  std::string predicate;

  // True for the problems an end (a parent's, or --duration) would solve.
  bool needs_an_end() const {
    return problem == ScheduleProblem::no_duration || problem == ScheduleProblem::endless_repeat;
  }
  // The problem as an error whose message is `subject predicate` (limit_exceeded for too many
  // runs, bad_input otherwise).
  Diagnostic diagnostic(std::string_view subject) const;
};

// The schedule, or the first problem met (with the node's source position and tag): a start
// before 0, align_right outside a parallel, a leaf or repeat with no duration and no parent end,
// more than max_runs runs.
std::variant<Schedule, ScheduleError> schedule_tree(const ScheduleNode& root,
                                                    const ScheduleOptions& options = {});

// schedule_tree for front ends whose nodes are all "actions" (Mimic): the error's subject is
// "the action" where the predicate needs one.
Result<Schedule> schedule(const ScheduleNode& root, const ScheduleOptions& options = {});

}  // namespace fapc
