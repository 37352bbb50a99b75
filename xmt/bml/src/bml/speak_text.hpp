// speech text to visemes and voice, with each sync mark at the onset of the word after it
// (docs/bml.md, "Speech").
#pragma once

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

// Speaks `text` with options.speech.synthesize, or by the letter table with a warning (once per
// document: `warned`). Errors at `where` (the engine's: language, limits).
Result<SpokenText> speak(const MarkedText& text, const ReaderOptions& options, const Location& where,
                         Diagnostics& warnings, bool& warned);

}  // namespace fapc::bml
