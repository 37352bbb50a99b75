#include "fapc/transcoder/curves.hpp"

#include <array>

namespace fapc {

Curves curves_from_frames(const FapSequence& sequence) {
  Curves out;
  out.fps = sequence.fps;
  out.duration = sequence.duration_seconds();
  // Each target's list, found in the map once (its node never moves) rather than once per point
  // by a name built for it: that lookup was most of the time on long animations.
  using Points = std::vector<std::pair<double, double>>;
  std::array<Points*, kFapCount + 1> list{};
  const auto points_of = [&](int fap) -> Points& {
    Points*& points = list[static_cast<std::size_t>(fap)];
    if (!points) points = &out.curves[fap == 1 ? "viseme" : fap == 2 ? "expression" : std::string(find_fap(fap)->name)];
    return *points;
  };
  for (const FapFrame& frame : sequence.frames) {
    const double t = static_cast<double>(frame.number) / sequence.fps;
    if (frame.has(1)) points_of(1).emplace_back(t, frame.viseme.select1);
    if (frame.has(2)) points_of(2).emplace_back(t, frame.expression.select1);
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (frame.has(fap)) points_of(fap).emplace_back(t, frame.value(fap));
  }
  return out;
}

}  // namespace fapc
