// The speech engine (docs/speech.md): eSpeak NG through its library API, synchronous, with
// phoneme events. This library is the only part of fapc that links libespeak-ng (GPL-3.0+), so a
// program that links it is GPL-3.0+ too; fapc::codec, fapc::transcoder and fapc::mpeg4 never do.
// Built without the engine (-DFAPC_SPEECH=OFF, or libespeak-ng not found), engine() is empty and
// callers fall back to the letter-to-viseme table with a warning.
#pragma once

#include <string>

#include "fapc/transcoder/speech.hpp"

namespace fapc::speech {

// True when this build has the engine.
bool available();

// "eSpeak NG 1.51" (the library's own version), or "none".
std::string engine_name();

// A synthesizer that speaks with eSpeak NG; an empty function when !available(). Calls from any
// thread are serialised (eSpeak NG keeps global state), and each is spoken in a child process
// of the speaker process (start_engine_process), so the same request gives the same samples
// whatever was spoken before (docs/speech.md, "Every utterance alike"). The engine's own messages come back as warnings
// (code speech.engine_message), never printed. Errors, at request.where: an unknown language or
// voice variant, a rate outside 80..450 words per minute, speech longer than request.max_seconds
// (limit_exceeded), an engine failure or crash.
Synthesizer engine();

// Starts the speaker: the process, forked from this one, whose children speak. Call it while this
// process has a single thread (at the start of main, before a batch's workers): a fork taken while
// other threads run may leave the child waiting for ever on a lock one of them held. False when
// other threads already run, or without the engine; the first utterance then starts the speaker
// itself, taking that risk once. Calling it again does nothing.
bool start_engine_process();

}  // namespace fapc::speech
