// What the speaker process is asked for one utterance (speaker_process.hpp), and what the child
// that spoke it gives back: the samples and events eSpeak NG called back with, and where it
// stopped. The reading end checks every count against the bytes it got.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fapc::speech {

struct EngineOutput {
  enum class Stop : std::uint8_t {
    spoken,            // every piece of the text was synthesised
    language_refused,  // espeak_SetVoiceByName refused the language
    voice_refused,     // ... or the language with its voice variant
    too_long,          // the samples reached the request's limit
    synth_failed,      // espeak_Synth returned `synth_status`
  };
  Stop stop = Stop::spoken;
  std::int32_t synth_status = 0;
  std::vector<std::int16_t> samples;
  std::vector<std::pair<std::string, std::int32_t>> phonemes;  // mnemonic (at most 8 bytes), start in ms
  std::vector<std::pair<std::int32_t, std::int32_t>> words;    // character position (from 1), start in ms
};

std::string encode(const EngineOutput& output);

// The synthesis asked for: speak() checked the names and the rate before sending it.
struct EngineRequest {
  std::string language;
  std::string voice;  // a variant, or empty
  std::int32_t words_per_minute = 0;
  std::uint64_t max_samples = 0;
  std::string text;
};

std::string encode(const EngineRequest& request);

// nullopt when `bytes` is not exactly one encoded EngineRequest.
std::optional<EngineRequest> decode_engine_request(std::string_view bytes);

// nullopt when `bytes` is not exactly one encoded EngineOutput.
std::optional<EngineOutput> decode_engine_output(std::string_view bytes);

}  // namespace fapc::speech
