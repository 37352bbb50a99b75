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
#include "fapc/transcoder/timeline.hpp"

namespace fapc::smil {

struct SmilOptions {
  // The most elements, and runs after repeats, a script may have: Limits::max_runs (--max-runs).
  std::int64_t max_runs = Limits{}.max_runs;
  // How speech is spoken and the frames the script will be rendered at, as for BML: the engine
  // (without one, the FML reader's letter table, silent, with a warning), the language where no
  // system-language is in force, the voice, rate, longest speech and coarticulation; a script
  // too long for `frames` is refused once scheduled. (max_behaviours is not read: max_runs is.)
  bml::BmlOptions speech;
  // The script's speech text and seconds, all speeches together (docs/security.md), checked
  // before any is spoken; the audio samples of `file=` recordings.
  Limits speech_limits;
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
