// speech text to visemes and voice, with each sync mark at the onset of the word after it
// (docs/bml.md, "Speech").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bml/bml_model.hpp"
#include "fapc/bml/bml.hpp"

namespace fapc::bml {

// The text to say and where each mark sits in it (byte offsets).
struct MarkedText {
  std::string text;
  std::vector<std::string> mark_ids;
  std::vector<std::size_t> mark_offsets;
};

// What one document has spoken so far. All of a document's speech together is bounded by the
// speech limits (docs/security.md), as FML's and SMIL-Agent's are: otherwise a document of many
// speeches, each under the frame limit, could keep the engine busy for hours.
struct SpeakingSoFar {
  std::int64_t text_bytes = 0;
  double seconds = 0;
  bool warned_no_engine = false;  // the letter-table warning is said once per document
};

// Speaks `text` with options.speech.synthesize, or by the letter table with a warning (once per
// document). Before the engine runs, the document's text and its estimated seconds are checked
// against Limits::max_speech_text_bytes and max_speech_seconds; the engine then stops at the
// seconds left. Errors at `where` (the limits', the engine's: language, limits).
Result<SpokenText> speak(const MarkedText& text, const ReaderOptions& options, const Location& where,
                         Diagnostics& warnings, SpeakingSoFar& so_far);

}  // namespace fapc::bml
