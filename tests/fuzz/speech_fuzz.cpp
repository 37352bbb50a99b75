// libFuzzer target: FML spoken by the real speech engine (eSpeak NG): talk text, `lang`, `voice`,
// repeats and far-apart begins. Nothing may crash the engine or the process (issue 32: stacked
// suffixes aborted eSpeak NG, hyphens crashed it), every error is placed at line:col, and an
// accepted story is a sane timeline whose voice fits the limits it was read under. The limits
// are small so that one input costs milliseconds, not seconds.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fapc/fml/fml.hpp"
#include "fapc/speech/engine.hpp"
#include "fapc/transcoder/audio_mix.hpp"
#include "timeline_checks.hpp"

// Before libFuzzer's own threads (its memory watch): fapc/speech/engine.hpp.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fapc::speech::start_engine_process();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  fapc::xmt::FmlOptions options;
  options.duration = 10;
  options.synthesize = fapc::speech::engine();
  options.speech_limits.max_speech_text_bytes = 4096;
  options.speech_limits.max_speech_seconds = 20;
  options.speech_limits.max_audio_samples = std::int64_t{1} << 22;
  options.max_speech_seconds = 20;
  const auto read = fapc::xmt::read_fml(text, "fuzz.fml", options);
  if (read.ok()) {
    auto mixed = fapc::mix_audio(read->timeline.audio, 1e6, options.speech_limits);
    if (mixed.ok() && *mixed &&
        static_cast<std::int64_t>((*mixed)->samples.size()) > options.speech_limits.max_audio_samples)
      std::abort();
    if (!mixed.ok() && mixed.error().kind != fapc::ErrorKind::limit_exceeded) std::abort();
  }
  return fapc::fuzz::check_timeline_read(read);
}
