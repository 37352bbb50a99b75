// FML-APML and APML as inputs (docs/intentions.md): intentions through the behaviour lexicon
// (fapc's own, or --lexicon FILE), drawn and spoken as BML is. Both are named .xml in the wild and
// reach these readers by their root element (format_xml.cpp).
#include "fapc/codec/file_io.hpp"
#include "fapc/intent/intent.hpp"
#include "formats.hpp"
#include "formats/bml_options.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline::builtin {

namespace {

nlohmann::ordered_json facts_of(const intent::IntentDocument& document, const std::string& lexicon) {
  nlohmann::ordered_json out;
  out["format"] = document.language;
  out["lexicon"] = lexicon;
  std::size_t drawn = 0;
  for (const intent::Intention& i : document.intentions) drawn += i.behaviours > 0 ? 1 : 0;
  out["intentions"] = document.intentions.size();
  out["intentions_drawn"] = drawn;
  if (!document.languages.empty()) out["speech_languages"] = document.languages;
  out["clips"] = document.timeline.clips.size();
  return out;
}

using Reader = Result<intent::IntentDocument> (*)(const std::string&, const intent::IntentOptions&);

Result<Loaded> load_with(Reader read, const std::string& path, const ConvertOptions& options) {
  Result<Profile> profile = profile_for(options);
  if (!profile) return profile.error();
  intent::IntentOptions intent_options;
  intent_options.bml = bml_options(options);
  vocabulary::BehaviourLexicon user_lexicon;
  if (options.lexicon) {
    const auto source = SourceText::open(*options.lexicon, options.limits);
    if (!source) return source.error();
    Result<vocabulary::BehaviourLexicon> parsed = vocabulary::parse_behaviour_lexicon(source->bytes(), *options.lexicon);
    if (!parsed) return parsed.error();
    user_lexicon = std::move(*parsed);
    user_lexicon.base = &vocabulary::bundled_behaviour_lexicon();  // what the file does not name
    intent_options.lexicon = &user_lexicon;
  }
  Result<intent::IntentDocument> document = read(path, intent_options);
  if (!document) return document.error();
  auto facts = options.facts ? facts_of(*document, options.lexicon.value_or("intentions.tsv (fapc's own)"))
                             : nlohmann::ordered_json::object();
  return loaded_from_timeline(std::move(document->timeline), path, *profile, options, std::move(document->warnings),
                              std::move(facts));
}

Result<Loaded> load_fml_apml(const std::string& path, const ConvertOptions& options) {
  return load_with(intent::load_fml_apml, path, options);
}

Result<Loaded> load_apml(const std::string& path, const ConvertOptions& options) {
  return load_with(intent::load_apml, path, options);
}

}  // namespace

InputFormat fml_apml_input() {
  InputFormat format{"fml-apml", {".fml-apml"}, load_fml_apml};
  format.timeline = true;
  return format;
}

InputFormat apml_input() {
  InputFormat format{"apml", {".apml"}, load_apml};
  format.timeline = true;
  return format;
}

}  // namespace fapc::pipeline::builtin
