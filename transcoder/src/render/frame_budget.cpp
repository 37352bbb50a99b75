#include "fapc/transcoder/frame_budget.hpp"

#include <cmath>
#include <cstdio>

namespace fapc {

bool FrameBudget::exceeded_by(double end) const {
  // Written so that a NaN end is refused too.
  return fps > 0 && !(std::ceil(end * fps) <= static_cast<double>(max_frames));
}

Diagnostic frame_budget_error(double end, const Location& where, const FrameBudget& budget) {
  char text[96];
  std::snprintf(text, sizeof text, "the animation lasts %g s, %.15g frames at %d fps", end, std::ceil(end * budget.fps),
                budget.fps);
  Limits limits;
  limits.max_frames = budget.max_frames;
  return limit_error(where, text, Limit::frames, limits);
}

}  // namespace fapc
