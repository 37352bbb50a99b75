// The one ReaderOptions of a conversion (fapc/transcoder/reader_options.hpp), made from its
// ConvertOptions for every script reader: the limits, the frame budget, the includes policy,
// events, --duration and the speech settings (--voice, --speech-rate, the engine of fapc::speech
// when this build has one: docs/speech.md).
#pragma once

#include "fapc/pipeline/options.hpp"
#include "fapc/transcoder/reader_options.hpp"

namespace fapc::pipeline {

// options.voice is LANGUAGE, LANGUAGE+VARIANT or +VARIANT ("fr", "fr+f3", "+m3"). `profile`: the
// names parameters may use (profile_for(options)); nullptr: the default profile.
ReaderOptions reader_options(const ConvertOptions& options, const Profile* profile = nullptr);

}  // namespace fapc::pipeline
