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
  return load_script(
      path, options, [&](const Profile&) { return smil::load_smil(path, smil_options(options)); }, facts_of);
}

}  // namespace

InputFormat smil_input() {
  InputFormat format{"smil", {".smil"}, load_smil};
  format.timeline = true;
  format.xml_roots = {"par", "seq"};  // Xface SMIL-Agent scripts have no root of their own
  return format;
}

}  // namespace fapc::pipeline::builtin
