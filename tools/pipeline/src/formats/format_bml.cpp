// .bml as an input: BML blocks (docs/bml.md). Speech is spoken as FML talk is (--voice,
// --speech-rate); --max-runs bounds the behaviours.
#include "fapc/bml/bml.hpp"
#include "formats.hpp"
#include "speech_options.hpp"
#include "timeline_input.hpp"

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
  out["clips"] = document.timeline.clips.size();
  return out;
}

Result<Loaded> load_bml(const std::string& path, const ConvertOptions& options) {
  Result<Profile> profile = profile_for(options);
  if (!profile) return profile.error();
  Result<bml::BmlDocument> document = bml::load_bml(path, bml_options(options));
  if (!document) return document.error();
  auto facts = options.facts ? facts_of(*document) : nlohmann::ordered_json::object();
  return loaded_from_timeline(std::move(document->timeline), path, *profile, options, std::move(document->warnings),
                              std::move(facts));
}

}  // namespace

InputFormat bml_input() {
  InputFormat format{"bml", {".bml"}, load_bml};
  format.timeline = true;
  return format;
}

}  // namespace fapc::pipeline::builtin
