// What one utterance's synthesis gives back from the child process that spoke it (forked_call.hpp):
// the samples and events eSpeak NG called back with, and where it stopped. Written by the child,
// read by the parent, which checks every count against the bytes it got.
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

// nullopt when `bytes` is not exactly one encoded EngineOutput.
std::optional<EngineOutput> decode_engine_output(std::string_view bytes);

}  // namespace fapc::speech
