#include "speech_options.hpp"

#include "fapc/speech/engine.hpp"
#include "timeline_input.hpp"

namespace fapc::pipeline {

void set_speech(fml::FmlOptions& fml, const ConvertOptions& options) {
  fml.synthesize = options.speech_engine ? speech::engine() : Synthesizer{};
  const std::string& voice = options.voice;
  const std::size_t plus = voice.find('+');
  const std::string language = voice.substr(0, plus);
  if (!language.empty()) fml.language = language;
  if (plus != std::string::npos) fml.voice = voice.substr(plus + 1);
  fml.words_per_minute = options.words_per_minute;
  // Speech may last as long as the frames may: the frame limit at the frame rate.
  fml.max_speech_seconds = static_cast<double>(options.limits.max_frames) / options.fps;
  fml.speech_limits = options.limits;
}

bml::BmlOptions bml_options(const ConvertOptions& options) {
  // The speech settings are the FML reader's: one place reads --voice and --speech-rate.
  fml::FmlOptions speech;
  set_speech(speech, options);
  bml::BmlOptions out;
  out.synthesize = std::move(speech.synthesize);
  out.language = speech.language;
  out.voice = speech.voice;
  out.words_per_minute = speech.words_per_minute;
  out.max_speech_seconds = speech.max_speech_seconds;
  out.coarticulation = speech.coarticulation;
  out.max_behaviours = options.limits.max_runs;
  out.frames = frame_budget_for(options);
  out.includes = options.includes;
  out.speech_limits = options.limits;
  return out;
}

}  // namespace fapc::pipeline
