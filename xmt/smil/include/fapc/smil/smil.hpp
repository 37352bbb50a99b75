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

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/speech.hpp"
#include "fapc/transcoder/timeline.hpp"

namespace fapc::smil {

struct SmilOptions {
  // The most elements, and runs after repeats, a script may have: Limits::max_runs (--max-runs).
  std::int64_t max_runs = Limits{}.max_runs;
  // The frames the script will be rendered at: a script too long for them is refused once it is
  // scheduled (fps 0: unchecked).
  FrameBudget frames;
  // speech text: spoken by `synthesize` (fapc::speech::engine()); without one, the FML reader's
  // letter table at words_per_minute, silent, with a warning. `language` is the default where no
  // system-language is in force.
  Synthesizer synthesize;
  std::string language = "en";
  std::string voice;
  double words_per_minute = 175;
  double max_speech_seconds = 3600;
  // The script's speech text and seconds, all speeches together (docs/security.md), checked
  // before any is spoken; the audio samples of `file=` recordings.
  Limits speech_limits;
  Coarticulation coarticulation;
  // Which files `speech file=` may name (docs/security.md); by default the script's folder tree.
  IncludePolicy includes;
};

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
Result<SmilDocument> read_smil(std::string_view text, const std::string& file_name, const SmilOptions& options = {});
Result<SmilDocument> load_smil(const std::string& path, const SmilOptions& options = {});

}  // namespace fapc::smil
