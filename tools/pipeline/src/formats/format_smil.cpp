// .smil as an input: Xface SMIL-Agent scripts (docs/smil.md). Speech is spoken as FML talk is
// (--voice, --speech-rate); --max-runs bounds the elements and runs; speech file= is an include.
#include "fapc/smil/smil.hpp"
#include "formats.hpp"
#include "speech_options.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline::builtin {

namespace {

smil::SmilOptions smil_options(const ConvertOptions& options) {
  smil::SmilOptions out;
  out.speech = bml_options(options);
  out.speech_limits = options.limits;
  out.max_runs = options.limits.max_runs;
  out.includes = options.includes;
  return out;
}

nlohmann::ordered_json facts_of(const smil::SmilDocument& document) {
  nlohmann::ordered_json out;
  out["format"] = "SMIL-Agent";
  out["speeches"] = document.speeches;
  std::size_t drawn = 0;
  for (const smil::PlacedBehaviour& b : document.behaviours) drawn += b.drawn ? 1 : 0;
  out["affects_and_actions"] = document.behaviours.size();
  out["affects_and_actions_drawn"] = drawn;
  if (!document.languages.empty()) out["speech_languages"] = document.languages;
  if (!document.recordings.empty()) out["recordings"] = document.recordings;
  out["clips"] = document.timeline.clips.size();
  return out;
}

Result<Loaded> load_smil(const std::string& path, const ConvertOptions& options) {
  Result<Profile> profile = profile_for(options);
  if (!profile) return profile.error();
  Result<smil::SmilDocument> document = smil::load_smil(path, smil_options(options));
  if (!document) return document.error();
  auto facts = options.facts ? facts_of(*document) : nlohmann::ordered_json::object();
  return loaded_from_timeline(std::move(document->timeline), path, *profile, options, std::move(document->warnings),
                              std::move(facts));
}

}  // namespace

InputFormat smil_input() {
  InputFormat format{"smil", {".smil"}, load_smil};
  format.timeline = true;
  return format;
}

}  // namespace fapc::pipeline::builtin
