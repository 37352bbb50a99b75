// Private: thinning a time-value list (docs/timeline.md, "Rendering").
#pragma once

#include <utility>
#include <vector>

namespace fapc {

// Drops every point whose value, linearly interpolated from its kept neighbours, is off by no more
// than `tolerance` times the list's value range. The first and last points, and both points of a
// jump (two points at one time), are always kept. In place: the kept points move to the front and
// the rest is cut off, the capacity staying (the caller samples its next list into it).
void thin_points(std::vector<std::pair<double, double>>& points, double tolerance);

}  // namespace fapc
