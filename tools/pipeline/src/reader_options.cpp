#include "reader_options.hpp"

#include "fapc/pipeline/registry.hpp"
#include "fapc/speech/engine.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline {

ReaderOptions reader_options(const ConvertOptions& options, const Profile* profile) {
  ReaderOptions out;
  out.limits = options.limits;
  out.frames = frame_budget_for(options);
  out.includes = options.includes;
  out.profile = profile;
  out.events = options.events;
  out.duration = options.duration;
  out.speech.synthesize = options.speech_engine ? speech::engine() : Synthesizer{};
  const std::string& voice = options.voice;
  const std::size_t plus = voice.find('+');
  const std::string language = voice.substr(0, plus);
  if (!language.empty()) out.speech.language = language;
  if (plus != std::string::npos) out.speech.voice = voice.substr(plus + 1);
  out.speech.words_per_minute = options.words_per_minute;
  // Speech may last as long as the frames may: the frame limit at the frame rate.
  out.speech.max_seconds = static_cast<double>(options.limits.max_frames) / options.fps;
  // What each row's reader takes, so that a reader handed another's document names the row's.
  for (const InputFormat& f : formats().inputs())
    for (const std::string& root : f.xml_roots) out.other_readers.push_back({root, f.kind, f.extensions.front()});
  return out;
}

}  // namespace fapc::pipeline
