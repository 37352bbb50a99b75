#include "user_lexicon.hpp"

#include "fapc/codec/file_io.hpp"

namespace fapc::pipeline {

Result<std::optional<vocabulary::BehaviourLexicon>> user_lexicon(const ConvertOptions& options) {
  if (!options.lexicon) return std::optional<vocabulary::BehaviourLexicon>{};
  const auto source = SourceText::open(*options.lexicon, options.limits);
  if (!source) return source.error();
  Result<vocabulary::BehaviourLexicon> parsed = vocabulary::parse_behaviour_lexicon(source->bytes(), *options.lexicon);
  if (!parsed) return parsed.error();
  parsed->base = &vocabulary::bundled_behaviour_lexicon();  // what the file does not name
  return std::optional<vocabulary::BehaviourLexicon>(std::move(*parsed));
}

}  // namespace fapc::pipeline
