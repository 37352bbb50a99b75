// What an input became: the value every reader returns and every writer takes.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/transcoder/curves.hpp"
#include "fapc/transcoder/timeline.hpp"

namespace fapc::pipeline {

// Always frames (unless ConvertOptions::render was false); the timeline and its curves when the
// front end has them (Mimic, FML, XMT-Omega), so curve outputs and per-clip plots keep the
// authored shape.
struct Loaded {
  FapSequence frames;
  std::optional<Curves> curves;
  std::optional<Timeline> timeline;
  Diagnostics warnings;
  // With ConvertOptions::facts: what the reader saw of the format (variant, stream statistics,
  // tracks...), by name; `fapc info` prints it. Found during the one read, never by a second one.
  nlohmann::ordered_json facts = nlohmann::ordered_json::object();
};

}  // namespace fapc::pipeline
