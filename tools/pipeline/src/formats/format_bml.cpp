// .bml as an input: BML blocks (docs/bml.md). Speech is spoken as FML talk is (--voice,
// --speech-rate); --max-runs bounds the behaviours; --lexicon draws the face lexemes and Greta
// references it names.
#include "fapc/bml/bml.hpp"
#include "fapc/pipeline/registry.hpp"
#include "reader_options.hpp"
#include "timeline_input.hpp"
#include "user_lexicon.hpp"

namespace fapc::pipeline::builtin {

namespace {

nlohmann::ordered_json facts_of(const bml::BmlDocument& document) {
  nlohmann::ordered_json out;
  out["format"] = "BML";
  out["dialect"] = document.dialect;
  out["blocks"] = document.blocks;
  bool any_character = false;
  for (const std::string& c : document.characters) any_character = any_character || !c.empty();
  if (any_character) out["characters"] = document.characters;
  std::size_t drawn = 0;
  for (const bml::ScheduledBehaviour& b : document.behaviours) drawn += b.drawn ? 1 : 0;
  out["behaviours"] = document.behaviours.size();
  out["behaviours_drawn"] = drawn;
  if (!document.languages.empty()) out["speech_languages"] = document.languages;
  if (!document.recordings.empty()) out["recordings"] = document.recordings;
  if (document.blocks.size() > 1) {  // a sequence (docs/bml.md, "Several blocks")
    out["compositions"] = document.compositions;
    out["block_starts"] = document.block_starts;
  }
  out["clips"] = document.timeline.clips.size();
  return out;
}

Result<Loaded> load_bml(const std::string& path, const ConvertOptions& options) {
  Result<std::optional<vocabulary::BehaviourLexicon>> lexicon = user_lexicon(options);
  if (!lexicon) return lexicon.error();
  const vocabulary::BehaviourLexicon* user = *lexicon ? &**lexicon : nullptr;
  return load_script(
      path, options, [&](const Profile&) { return bml::load_bml(path, reader_options(options), user); }, facts_of);
}

Result<Loaded> load_bml_sequence(const std::string& path, const ConvertOptions& options) {
  return load_script(
      path, options, [&](const Profile&) { return bml::load_bml_sequence(path, reader_options(options)); }, facts_of);
}

}  // namespace

// .bmlseq: BML documents given in order, one per line (docs/bml.md, "Several blocks").
InputFormat bml_sequence_input() {
  InputFormat format{"bmlseq", {".bmlseq"}, load_bml_sequence};
  format.timeline = true;
  return format;
}

InputFormat bml_input() {
  InputFormat format{"bml", {".bml"}, load_bml};
  format.timeline = true;
  format.xml_roots = {"bml"};
  return format;
}

}  // namespace fapc::pipeline::builtin
