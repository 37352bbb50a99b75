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
#include "fapc/timeline/timeline.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/reader_options.hpp"
#include "fapc/transcoder/speech.hpp"
#include "fapc/vocabulary/behaviour_lexicon.hpp"

namespace fapc::bml {

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
  // Per block, with `blocks`: its composition (MERGE, APPEND, REPLACE) and where it was placed
  // (seconds from the start; 0 for a document read alone, docs/bml.md "Several blocks").
  std::vector<std::string> compositions;
  std::vector<double> block_starts;
};

// Errors (file:line:col): not well-formed XML, another root than bml, malformed sync references,
// references to unknown behaviours or sync points, constraints that cannot hold together (named
// with the chain of constraints that forces the contradiction), a behaviour that would start
// before its block. `lexicon`, when given, is a user's behaviour lexicon (--lexicon, docs/bml.md
// "A lexicon of your own"): its faceLexeme rows draw the lexemes they name, its face, head and
// gaze rows the Greta references they name, before fapc's own tables.
Result<BmlDocument> read_bml(std::string_view text, const std::string& file_name, const ReaderOptions& options = {},
                             const vocabulary::BehaviourLexicon* lexicon = nullptr);
Result<BmlDocument> load_bml(const std::string& path, const ReaderOptions& options = {},
                             const vocabulary::BehaviourLexicon* lexicon = nullptr);

// Several BML documents given in order, as a realizer receives blocks (docs/bml.md, "Several
// blocks"): `list` holds one document per line (`[at SECONDS] PATH`, `#` comments), each path
// relative to the list's folder and read under options.includes. Each block is placed by its
// composition: MERGE starts when it arrives, APPEND when every earlier block has ended, REPLACE
// when it arrives, cutting what earlier blocks still run there. A block arrives with the one
// before it (the first at 0) unless its line says when. Errors are placed in the list (a path or
// time that cannot be read) or in the document.
Result<BmlDocument> read_bml_sequence(std::string_view list, const std::string& list_name,
                                      const ReaderOptions& options = {});
Result<BmlDocument> load_bml_sequence(const std::string& path, const ReaderOptions& options = {});

}  // namespace fapc::bml
