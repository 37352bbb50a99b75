// The SMIL-Agent reader (docs/smil.md): Xface's scripts of an agent's speech, affects and eye and
// head actions in SMIL par/seq containers, lowered to the shared timeline. Speech is spoken by the
// engine with its marks at their words; speech-animation affects and actions anchored to a
// speech's marks become BML behaviours (an affect through fapc's smil_affects.tsv) drawn by the
// BML reader's own lowering.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/bml/bml.hpp"
#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fapc/transcoder/reader_options.hpp"

namespace fapc::smil {

// One affect or action as placed, for `fapc info` and the tests.
struct PlacedBehaviour {
  std::string element;  // "speech-animation", "action"
  std::string name;     // the affect, or the action's type and first parameter ("turning LookLeft")
  double start = 0;
  double end = 0;
  bool drawn = true;  // false: unknown, kept for its span only (with a warning)
};

struct SmilDocument {
  Timeline timeline;
  std::vector<std::string> speeches;   // speech ids (or "" when none), in document order
  std::vector<std::string> languages;  // the languages speech was spoken in
  std::vector<PlacedBehaviour> behaviours;
  std::vector<std::string> recordings;  // resolved paths of speech file=
  Diagnostics warnings;
};

// Errors (file:line:col): not well-formed XML, another root than par or seq, malformed clock
// values, fill, repeat or intensity, a content-id naming no speech, a content-begin/content-end
// naming no mark of it, a speech file= outside the allowed folders or not a 16-bit PCM WAV, and
// the limits (elements and runs, speech text and seconds, audio samples, frames).
Result<SmilDocument> read_smil(std::string_view text, const std::string& file_name, const ReaderOptions& options = {});
Result<SmilDocument> load_smil(const std::string& path, const ReaderOptions& options = {});

}  // namespace fapc::smil
