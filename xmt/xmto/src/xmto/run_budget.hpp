// A bound on how many runs (scheduled occurrences) a document asks for, checked before scheduling:
// repeatCount="1e9", or a 1 ms animation repeated for an hour, would otherwise make millions of
// clips. The bound uses what each element states about itself (dur, repeatCount, repeatDur, end)
// and the time its ancestors leave it; it is loose, never lower than the real count where those
// are given.
#pragma once

#include <limits>
#include <optional>

#include "xmto/smil_timing.hpp"

namespace fapc::xmt {

struct RunBudget {
  double available = std::numeric_limits<double>::infinity();  // time the parent leaves
  double repeats = 1;                                          // product of the repeat factors of the ancestors

  // The budget of an element's children (or, for a leaf, its own runs in `repeats`).
  // `implicit`: the simple duration when dur is absent (an included animation's length).
  RunBudget inside(const SmilTiming& timing, std::optional<double> implicit) const;
};

}  // namespace fapc::xmt
