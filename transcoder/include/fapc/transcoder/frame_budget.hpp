// How many frames an animation may take (Limits::max_frames), checked where its length is first
// known. A script's front end checks it as soon as its schedule gives the end, before any clip is
// made, so that a script of a million elements too long for the limit is refused in the time of
// reading it, not of lowering it as well (docs/security.md, "Resource limits"); FrameStream::start checks
// the same before its first frame. Both give the same error.
#pragma once

#include <cstdint>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/limits.hpp"

namespace fapc {

struct FrameBudget {
  int fps = 0;  // the rate the animation will be rendered at; 0: its frames are never made, nothing is checked
  std::int64_t max_frames = Limits{}.max_frames;

  // Whether an animation ending at `end` seconds takes more frames than max_frames at fps.
  bool exceeded_by(double end) const;
};

// The limit_exceeded error for an animation ending at `end` (exceeded_by(end)); `where` is the
// source of its end: the element that ends last, or the input ended by --duration.
Diagnostic frame_budget_error(double end, const Location& where, const FrameBudget& budget);

}  // namespace fapc
