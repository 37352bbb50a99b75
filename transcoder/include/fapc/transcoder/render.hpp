// Rendering the shared timeline (docs/timeline.md, "Rendering"): blended values at any time, frames
// at a frame rate, and thinned time-value lists. No I/O; clamps come back as warnings.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fapc/transcoder/curves.hpp"
#include "fapc/transcoder/profile.hpp"

namespace fapc {

// Answers value queries on one timeline. Construction indexes the clips per target and resolves
// fill=freeze ends; queries cost O(log n + active clips).
class TimelineEvaluator {
 public:
  explicit TimelineEvaluator(const Timeline& timeline);

  std::vector<std::string> targets() const;  // sorted
  // The blended value of `target` at t; 0 (neutral) where no clip is active. `from_left` takes the
  // limit from the left (clips active on (begin, end]): the value a span has at its own end.
  double value_at(const std::string& target, double t, bool from_left = false) const;
  // [first begin, last end) of the target's clips, counting frozen clips to their resolved end.
  std::pair<double, double> span(const std::string& target) const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

struct RenderOptions {
  int fps = 25;
  const Profile* profile = nullptr;               // nullptr: default_profile()
  std::string name;                               // the sequence's name
  std::int64_t max_frames = Limits{}.max_frames;  // more frames is a limit_exceeded error
};

struct Rendered {
  FapSequence frames;
  Diagnostics warnings;  // clamps, once per clip, at the clip's source
};

// Frames k = 0 .. ceil(end * fps) - 1 at time k / fps. Errors: a target no profile maps, more
// than options.max_frames frames (at the timeline's end_source, or the clip that ends last).
Result<Rendered> render_frames(const Timeline& timeline, const RenderOptions& options);

// Where a too-long animation is reported: what the front end says ends it, else the clip that
// ends last (empty for a timeline without clips).
Location where_it_ends(const Timeline& timeline);

// The same frames one at a time, for writers that never hold them all (an encoder that takes two
// passes renders them twice: rendering is deterministic). start() makes every check render_frames
// makes before its first frame; the timeline must outlive the stream.
class FrameStream {
 public:
  static Result<FrameStream> start(const Timeline& timeline, const RenderOptions& options);
  FrameStream(FrameStream&&) noexcept;
  FrameStream& operator=(FrameStream&&) noexcept;
  ~FrameStream();

  std::int64_t count() const;  // ceil(end * fps)
  const std::string& name() const;
  int fps() const;
  // Frame k (0 <= k < count()), in any order.
  FapFrame frame(std::int64_t k);
  // The clamp warnings met so far, once per clip, in the order the frames met them.
  const Diagnostics& warnings() const;

 private:
  struct State;
  explicit FrameStream(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

struct CurveOptions {
  int fps = 25;
  double tolerance = 1e-6;  // relative to the target's value range
};

// Per target: the blended curve sampled at the frame rate plus every key-point time and span
// end, then thinned (docs/timeline.md, "Rendering").
Curves render_curves(const Timeline& timeline, const CurveOptions& options);

// Per clip, its own unblended curve, labelled "target (file:line)": the upper plot of Mimic Figure
// 1 (docs/mimic.md, "The paper").
Curves render_clip_curves(const Timeline& timeline, const CurveOptions& options);

}  // namespace fapc
