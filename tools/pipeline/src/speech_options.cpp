#include "speech_options.hpp"

#include "fapc/speech/engine.hpp"

namespace fapc::pipeline {

void set_speech(xmt::FmlOptions& fml, const ConvertOptions& options) {
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

}  // namespace fapc::pipeline
