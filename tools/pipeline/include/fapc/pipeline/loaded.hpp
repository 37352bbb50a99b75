// What an input became: the value every reader returns and every writer takes.
#pragma once

#include <bitset>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/pipeline/json_value.hpp"
#include "fapc/timeline/audio.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fapc/transcoder/curves.hpp"

namespace fapc::pipeline {

// What an input's frames were, for summaries (frame count, rate, FAPs used, duration), also
// when they went through without being held.
struct FramesSeen {
  FramesSeen() = default;
  FramesSeen(std::size_t count_, int fps_, std::bitset<kFapCount> faps_, std::optional<std::int64_t> last_number_ = {})
      : count(count_), fps(fps_), faps(faps_), last_number(last_number_) {}

  std::size_t count = 0;
  int fps = 25;
  std::bitset<kFapCount> faps;  // used by any frame
  // The last frame's number; absent when the frames are numbered 0 .. count - 1.
  std::optional<std::int64_t> last_number;
  // As FapSequence::duration_seconds: (last number + 1) / fps, 0 when there are none.
  double duration_seconds() const {
    if (count == 0 || fps <= 0) return 0.0;
    return static_cast<double>(last_number ? *last_number + 1 : static_cast<std::int64_t>(count)) / fps;
  }
};

// Always frames (unless ConvertOptions::render or ::frames was false); the timeline and its curves when the
// front end has them (Mimic, FML, XMT-Omega), so curve outputs and per-clip plots keep the
// authored shape.
struct Loaded {
  std::string origin;  // the input it came from (load() sets it): errors of writers name it

  // The file errors about these frames name: the input, or `output` when there is none.
  const std::string& named(const std::string& output) const { return origin.empty() ? output : origin; }
  FapSequence frames;
  // Set when a timeline's frames were rendered but not kept (ConvertOptions::frames false: no
  // output reads them): what they were. `frames` then has their name and rate, and no frames.
  std::optional<FramesSeen> frames_not_kept;
  // Where the input wrote the frames' rate (a .fap header), for errors about the rate; empty
  // when it came from an option or a default. `rate_written` is the rate written there.
  Location rate_at;
  int rate_written = 0;
  // Frame k's line in the input text (a .fap's value line), for placing an encoder's error about
  // one frame; empty when the frames were not read from lines.
  std::vector<int> frame_lines;
  std::optional<Curves> curves;
  std::optional<Timeline> timeline;
  // The sound that goes with the frames (the timeline's audio mixed, or a container's audio
  // track); absent when the input has none. Writers that can carry audio carry it.
  std::optional<AudioTrack> audio;
  Diagnostics warnings;
  // With ConvertOptions::facts: what the reader saw of the format (variant, stream statistics,
  // tracks...), by name; `fapc info` prints it. Found during the one read, never by a second one.
  JsonValue facts;
};

}  // namespace fapc::pipeline
