// Scheduling BML as constraint solving over sync points (docs/bml.md, "Scheduling"). Every
// behaviour has the seven standard sync points (start, ready, strokeStart, stroke, strokeEnd,
// relax, end) at default offsets from its start, and a rigid one (speech) marks of its own.
//
// Equalities (`start="h2:start-2"`, `<synchronize>`) join points into classes by a weighted
// union-find: each point's time is its class's time plus a fixed offset. A constraint joining two
// points already in one class at another offset is a contradiction, named with the chain of
// constraints that joined them. The class holding the block's start is placed; a behaviour then
// places its other classes by its default offsets (breadth first, from the placed classes); a
// group of classes tied to no time is placed as early as its behaviours allow (none before its
// block), and moved later where an `after`/`before` asks. Points no constraint names are placed
// between the named ones in proportion to their defaults. Every step is linear in the behaviours
// and constraints (the union-find's near-constant factor aside), chains of references included.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace fapc::bml {

inline constexpr std::uint32_t kStandardPoints = 7;
enum SyncPointIndex : std::uint32_t { kStart, kReady, kStrokeStart, kStroke, kStrokeEnd, kRelax, kEnd };

struct SolverBehaviour {
  std::array<double, kStandardPoints> defaults{};  // offsets from the start, non-decreasing, [0] = 0
  std::vector<double> marks;                       // further points (speech sync marks), offsets from the start
  bool rigid = false;                              // every point stays at its default offset (speech: its audio)
  int own_label = -1;                              // names the rigid timing in chains
};

struct PointRef {
  std::uint32_t behaviour = 0;
  std::uint32_t point = 0;  // < kStandardPoints: standard; else marks[point - kStandardPoints]
};

// equal: t(a) = t(b) + offset, or offset seconds after the block's start when b is absent.
// at_least: t(a) >= t(b) + offset (an `after`; a `before` is written the other way round).
struct Relation {
  enum class Kind : std::uint8_t { equal, at_least };
  Kind kind = Kind::equal;
  PointRef a;
  std::optional<PointRef> b;
  double offset = 0;
  int label = 0;  // the caller's name for the constraint (its place in the document)
};

struct SolveError {
  enum class What : std::uint8_t {
    contradiction,  // `label` joins two points that `chain` already holds at another distance
    order,          // behaviour's point `point` would come before its point `other`
    before_block,   // behaviour would start before its block (at `time`)
    unmet,          // the at_least `label` cannot hold: its points are tied to fixed times
  };
  What what = What::contradiction;
  int label = 0;
  std::vector<int> chain;  // the labels that force the other side, in order
  std::uint32_t behaviour = 0;
  std::uint32_t point = 0;
  std::uint32_t other = 0;
  double time = 0;        // the time the constraint asks for
  double other_time = 0;  // the time the chain gives
  bool absolute = false;  // contradiction: the times are from the block's start, not distances
};

struct Solution {
  std::vector<std::array<double, kStandardPoints>> points;  // per behaviour, seconds from the block's start
  std::vector<std::vector<double>> marks;
};

// An error, or every point's time. `relations` in document order: the first that cannot hold is
// the one named.
struct Solved {
  std::optional<SolveError> error;
  Solution solution;
};
Solved solve(const std::vector<SolverBehaviour>& behaviours, const std::vector<Relation>& relations);

}  // namespace fapc::bml
