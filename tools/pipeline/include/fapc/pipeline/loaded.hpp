// What an input became: the value every reader returns and every writer takes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/transcoder/audio.hpp"
#include "fapc/transcoder/curves.hpp"
#include "fapc/transcoder/timeline.hpp"

namespace fapc::pipeline {

// Always frames (unless ConvertOptions::render was false); the timeline and its curves when the
// front end has them (Mimic, FML, XMT-Omega), so curve outputs and per-clip plots keep the
// authored shape.
struct Loaded {
  std::string origin;  // the input it came from (load() sets it): errors of writers name it

  // The file errors about these frames name: the input, or `output` when there is none.
  const std::string& named(const std::string& output) const { return origin.empty() ? output : origin; }
  FapSequence frames;
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
  nlohmann::ordered_json facts = nlohmann::ordered_json::object();
};

}  // namespace fapc::pipeline
