// The BML reader (docs/bml.md): Behavior Markup Language 1.0 blocks (the SAIBA framework's
// language of behaviour realizers) lowered to the shared timeline. Behaviours are placed by
// solving their sync constraints (bml/sync_solver.hpp); face, head and gaze behaviours become FAP
// clips through fapc's vocabulary, speech is spoken by the engine with its sync marks at their
// words, and behaviours fapc does not draw keep their timing for the others to sync to.
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

namespace fapc::bml {

struct BmlOptions {
  // The most behaviours (and sync points) a document may hold: Limits::max_runs (--max-runs).
  std::int64_t max_behaviours = Limits{}.max_runs;
  // The frames the document will be rendered at: a document too long for them is refused once
  // scheduled (fps 0: unchecked).
  FrameBudget frames;
  // speech text: spoken by `synthesize` (fapc::speech::engine()); without one, the letter table
  // of the FML reader at words_per_minute, with a warning.
  Synthesizer synthesize;
  std::string language = "en";
  std::string voice;
  double words_per_minute = 175;
  double max_speech_seconds = 3600;
  Coarticulation coarticulation;
  // Recorded speech (SmartBody's <file ref>): which files may be read, and how large they may be
  // (max_decompressed_bytes, max_audio_samples).
  IncludePolicy includes;
  Limits speech_limits;
};

// One behaviour as scheduled, for `fapc info` and the tests.
struct ScheduledBehaviour {
  std::string block;
  std::string id;
  std::string element;  // "faceLexeme", "head", "gesture", ...
  double start = 0;
  double end = 0;
  bool drawn = true;  // false: kept for its timing only (gesture, posture, ...)
};

// A speech's sync mark as placed (the onset of the word after it), for readers that anchor
// their own spans to marks (FML-APML's intentions, docs/intentions.md).
struct ScheduledMark {
  std::string behaviour;  // the speech's id
  std::string id;
  double time = 0;  // seconds from the document's start
};

struct BmlDocument {
  Timeline timeline;
  std::string dialect;                  // "BML 1.0", ...
  std::vector<std::string> blocks;      // block ids in order
  std::vector<std::string> characters;  // characterId of each block ("" when none)
  std::vector<ScheduledBehaviour> behaviours;
  std::vector<ScheduledMark> marks;
  std::vector<std::string> languages;   // the languages speech was spoken in
  std::vector<std::string> recordings;  // the audio files of recorded speech that were read
  Diagnostics warnings;
};

// Errors (file:line:col): not well-formed XML, another root than bml, malformed sync references,
// references to unknown behaviours or sync points, constraints that cannot hold together (named
// with the chain of constraints that forces the contradiction), a behaviour that would start
// before its block.
Result<BmlDocument> read_bml(std::string_view text, const std::string& file_name, const BmlOptions& options = {});
Result<BmlDocument> load_bml(const std::string& path, const BmlOptions& options = {});

}  // namespace fapc::bml
