// Intentions to a face (docs/intentions.md): Greta's FML-APML (a bml part with the speech and its
// tm marks, an fml part of intentions anchored to the marks) and APML (intentions marked up over
// the spoken text) become behaviours through the behaviour lexicon
// (fapc/vocabulary/behaviour_lexicon.hpp) and are drawn by the BML reader's lowering, with the
// speech spoken by the same engine; so they reach every output a BML document does.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/bml/bml.hpp"
#include "fapc/vocabulary/behaviour_lexicon.hpp"

namespace fapc::intent {

struct IntentOptions {
  // Speech (engine, voice, rate), the behaviour limit (max_behaviours also bounds the
  // intentions: --max-runs) and the frame budget, as for BML.
  bml::BmlOptions bml;
  // The lexicon to read intentions by; null: fapc's own (data/intentions.tsv).
  const vocabulary::BehaviourLexicon* lexicon = nullptr;
};

// One intention as placed, for `fapc info` and the tests.
struct Intention {
  std::string id;
  std::string type;     // "emotion", "performative", "emphasis", "affect", ...
  std::string value;    // "joy", "inform", "Hstar", ...; "" when none is given
  double strength = 1;  // importance (FML-APML), intensity or activation (APML): scales the amounts
  double start = 0;     // seconds
  double end = 0;
  int behaviours = 0;  // lexicon rows drawn for it (0: unknown or drawn as nothing)
  Location where;
};

struct IntentDocument {
  Timeline timeline;
  std::string language;  // "FML-APML" or "APML"
  std::vector<Intention> intentions;
  std::vector<std::string> languages;  // the languages speech was spoken in
  Diagnostics warnings;
};

// A point intention (APML's boundary, an FML-APML intention without end) lasts this long.
inline constexpr double kPointSpanSeconds = 0.5;

// Errors (file:line:col): not well-formed XML, another root, a start or end that is neither a time
// nor a reference to a speech mark or to another behaviour or intention (named, with what exists),
// references in a cycle, an end before its start, importance or intensity outside 0..1, more
// intentions than options.bml.max_behaviours (--max-runs), a document longer than the frames.
// Unknown intentions and values are warnings (intent.unknown_intention) and keep their span.
Result<IntentDocument> read_fml_apml(std::string_view text, const std::string& file_name,
                                     const IntentOptions& options = {});
Result<IntentDocument> load_fml_apml(const std::string& path, const IntentOptions& options = {});
Result<IntentDocument> read_apml(std::string_view text, const std::string& file_name,
                                 const IntentOptions& options = {});
Result<IntentDocument> load_apml(const std::string& path, const IntentOptions& options = {});

}  // namespace fapc::intent
