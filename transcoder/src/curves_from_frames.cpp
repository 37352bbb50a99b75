#include "fapc/transcoder/curves.hpp"

namespace fapc {

Curves curves_from_frames(const FapSequence& sequence) {
  Curves out;
  out.fps = sequence.fps;
  out.duration = sequence.duration_seconds();
  for (const FapFrame& frame : sequence.frames) {
    const double t = static_cast<double>(frame.number) / sequence.fps;
    if (frame.has(1)) out.curves["viseme"].emplace_back(t, frame.viseme.select1);
    if (frame.has(2)) out.curves["expression"].emplace_back(t, frame.expression.select1);
    for (int fap = 3; fap <= kFapCount; ++fap)
      if (frame.has(fap))
        out.curves[std::string(find_fap(fap)->name)].emplace_back(t, frame.value(fap));
  }
  return out;
}

}  // namespace fapc
