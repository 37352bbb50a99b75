// The one scheduler of the project (docs/timeline.md): resolves a tree of sequences, parallels and
// exclusive groups into absolute intervals for its leaves. Every front end (Mimic, FML, XMT-Omega)
// builds a ScheduleNode tree from its source, calls schedule(), and makes clips from the
// occurrences. It knows timing only, nothing about curves.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/limits.hpp"

namespace fapc::timeline {

// std::optional<double> in 8 bytes instead of 16: "no value" is one NaN bit pattern that no
// arithmetic produces (a quiet NaN with a payload), so every double, NaN included, stays a value.
// Reads and assigns like the optional. A schedule tree has a node per element, each with four.
class OptionalSeconds {
 public:
  constexpr OptionalSeconds() = default;
  constexpr OptionalSeconds(std::nullopt_t) {}                   // NOLINT
  constexpr OptionalSeconds(double value) : value_(value) {}     // NOLINT
  constexpr OptionalSeconds(const std::optional<double>& value)  // NOLINT
      : value_(value ? *value : none()) {}

  constexpr bool has_value() const { return std::bit_cast<std::uint64_t>(value_) != kNone; }
  constexpr explicit operator bool() const { return has_value(); }
  constexpr const double& operator*() const { return value_; }
  constexpr double& operator*() { return value_; }
  constexpr double value() const {
    if (!has_value()) throw std::bad_optional_access();
    return value_;
  }
  constexpr double value_or(double otherwise) const { return has_value() ? value_ : otherwise; }
  constexpr void reset() { value_ = none(); }
  constexpr operator std::optional<double>() const {  // NOLINT
    return has_value() ? std::optional<double>(value_) : std::nullopt;
  }

  friend constexpr bool operator==(const OptionalSeconds& a, const OptionalSeconds& b) {
    return a.has_value() == b.has_value() && (!a.has_value() || a.value_ == b.value_);
  }

 private:
  static constexpr std::uint64_t kNone = 0x7FF8'0000'0000'DEADull;
  static constexpr double none() { return std::bit_cast<double>(kNone); }
  double value_ = none();
};

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
  OptionalSeconds duration;
  // The end, measured like offset from the default start; wins over duration (the active
  // duration becomes end - offset).
  OptionalSeconds end;
  // Only in parallels: end at the parallel's reference end + x (the start moves, the duration
  // stays). Mimic's `right` / `right=x`.
  OptionalSeconds align_right;
  double repeat = 1;                // iterations, may be fractional (SMIL repeatCount)
  bool repeat_indefinite = false;   // until the parent's end; an error when there is none
  OptionalSeconds repeat_duration;  // caps the active duration (SMIL repeatDur)
};

// 128 bytes: the tree has a node per element of the script.
struct ScheduleNode {
  enum class Kind : std::uint8_t { leaf, sequence, parallel, exclusive };
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
  // The most runs (occurrences) a schedule may have; more is a limit_exceeded error at the node
  // that repeats (Limits::max_runs, --max-runs).
  std::int64_t max_runs = Limits{}.max_runs;
};

struct Schedule {
  std::vector<Occurrence> occurrences;  // in tree order (depth first), then by iteration
  double end = 0;                       // the root's active end
};

// Where a schedule ends, for errors about the animation's length (Timeline::end_source): the
// source of the run that ends last when it ends with the schedule, else `root` (a group that
// outlasts every leaf). `leaf_source(leaf_id)` gives a leaf's source.
template <class LeafSource>
Location end_source(const Schedule& schedule, const Location& root, LeafSource leaf_source) {
  Location where = root;
  double last_end = -1;
  for (const Occurrence& run : schedule.occurrences)
    if (run.end >= last_end) {
      last_end = run.end;
      if (run.end >= schedule.end) where = leaf_source(run.leaf_id);
    }
  return where;
}

// Why a tree cannot be scheduled, as a value: front ends decide by `problem` and name the
// element by `node_tag`, never by the wording.
enum class ScheduleProblem {
  no_duration,         // a leaf with no duration and nothing around it ends
  endless_repeat,      // a group repeats indefinitely and nothing around it ends
  starts_before_zero,  // a leaf would start before time 0
  right_without_end,   // aligned right in a parallel whose end is unknown
  right_in_sequence,   // aligned right outside a parallel
  too_many_runs,       // more than ScheduleOptions::max_runs runs (a limit, --max-runs)
  ends_too_late,       // a leaf would end after the latest time fapc schedules
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
std::variant<Schedule, ScheduleError> schedule_tree(const ScheduleNode& root, const ScheduleOptions& options = {});

// schedule_tree for front ends whose nodes are all "actions" (Mimic): the error's subject is
// "the action" where the predicate needs one.
Result<Schedule> schedule(const ScheduleNode& root, const ScheduleOptions& options = {});

}  // namespace fapc::timeline

// Until the tree names the model fapc::timeline::..., the names are seen from fapc as before.
namespace fapc {
using namespace timeline;
}  // namespace fapc
