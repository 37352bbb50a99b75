// .fml as an input: FML documents (docs/fml.md). --event chooses excl branches, --duration ends
// indefinite loops, --profile names the parameters of param moves.
#include "fapc/fml/fml.hpp"
#include "formats.hpp"
#include "speech_options.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline::builtin {

namespace {

Result<xmt::FmlDocument> read_document(const std::string& path, const ConvertOptions& options, const Profile& profile) {
  xmt::FmlOptions fml;
  fml.events = options.events;
  fml.duration = options.duration;
  fml.max_runs = options.limits.max_runs;
  fml.frames = frame_budget_for(options);
  set_speech(fml, options);
  fml.profile = &profile;
  fml.includes = options.includes;
  return xmt::load_fml(path, fml);
}

nlohmann::ordered_json facts_of(const xmt::FmlDocument& document) {
  nlohmann::ordered_json out;
  out["format"] = "FML";
  if (!document.character.empty()) out["character"] = document.character;
  if (!document.events.empty()) {
    nlohmann::ordered_json events = nlohmann::ordered_json::object();
    for (const auto& [name, value] : document.events) events[name] = value;  // "" when it has no value
    out["events"] = events;
  }
  if (!document.templates.empty()) out["templates"] = document.templates;
  if (!document.phoneme_files.empty()) out["phoneme_files"] = document.phoneme_files;
  out["clips"] = document.timeline.clips.size();
  return out;
}

Result<Loaded> load_fml(const std::string& path, const ConvertOptions& options) {
  return load_script(
      path, options, [&](const Profile& profile) { return read_document(path, options, profile); }, facts_of);
}

}  // namespace

InputFormat fml_input() {
  InputFormat format{"fml", {".fml"}, load_fml};
  format.timeline = true;
  format.xml_roots = {"fml"};
  return format;
}

}  // namespace fapc::pipeline::builtin
