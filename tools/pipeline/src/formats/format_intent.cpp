// FML-APML and APML as inputs (docs/intentions.md): intentions through the behaviour lexicon
// (fapc's own, or --lexicon FILE), drawn and spoken as BML is. Both are named .xml in the wild and
// reach these readers by their root element (format_xml.cpp).
#include <optional>

#include "fapc/intent/intent.hpp"
#include "fapc/pipeline/registry.hpp"
#include "reader_options.hpp"
#include "timeline_input.hpp"
#include "user_lexicon.hpp"

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
  Result<std::optional<vocabulary::BehaviourLexicon>> lexicon = user_lexicon(options);
  if (!lexicon) return lexicon.error();
  intent::IntentOptions intent_options(reader_options(options));
  if (*lexicon) intent_options.lexicon = &**lexicon;
  const std::string lexicon_name = options.lexicon.value_or("intentions.tsv (fapc's own)");
  return load_script(
      path, options, [&](const Profile&) { return read(path, intent_options); },
      [&](const intent::IntentDocument& d) { return facts_of(d, lexicon_name); });
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
  format.xml_roots = {"fml-apml"};
  return format;
}

InputFormat apml_input() {
  InputFormat format{"apml", {".apml"}, load_apml};
  format.timeline = true;
  format.xml_roots = {"apml"};
  return format;
}

}  // namespace fapc::pipeline::builtin
