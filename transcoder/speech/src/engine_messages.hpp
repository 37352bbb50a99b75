// What eSpeak NG writes to standard error (it prints, as a command-line program would): the
// faults of its data ("Full dictionary is not installed for 'be'", "espeak: No envelope",
// "Bad intonation data", ...). The child that speaks (forked_call.hpp) catches them; they come
// back as warnings at the talk, since each says the voice may not sound as it should.
#pragma once

#include <cstddef>
#include <string_view>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::speech {

// The most bytes of the engine's messages kept for one utterance; the rest is counted.
inline constexpr std::size_t kMaxEngineMessageBytes = 4096;

// One warning (code speech.engine_message) per distinct line of `messages`, in order, each quoted
// up to 200 bytes with its control characters replaced; one more when `dropped` bytes were cut.
Diagnostics engine_message_warnings(std::string_view messages, std::size_t dropped, const Location& where);

}  // namespace fapc::speech
