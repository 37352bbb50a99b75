// The user's behaviour lexicon (--lexicon, docs/intentions.md "A lexicon of your own"), read once
// for a conversion by every reader that draws through the lexicon: FML-APML and APML intentions,
// BML face lexemes and Greta references (docs/bml.md).
#pragma once

#include <optional>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/pipeline/options.hpp"
#include "fapc/vocabulary/behaviour_lexicon.hpp"

namespace fapc::pipeline {

// The file over fapc's own intentions.tsv (its base), or nothing when no --lexicon is given.
// Errors: the file cannot be opened or is over the size limit, a row is malformed (at its line
// and column), more rows than vocabulary::kMaxLexiconRows.
Result<std::optional<vocabulary::BehaviourLexicon>> user_lexicon(const ConvertOptions& options);

}  // namespace fapc::pipeline
