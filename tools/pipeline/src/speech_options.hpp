// The speech settings of a conversion (--voice, --speech-rate) handed to the FML reader, with the
// engine of fapc::speech when this build has one (docs/speech.md).
#pragma once

#include "fapc/bml/bml.hpp"
#include "fapc/fml/fml.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::pipeline {

// Sets fml's synthesizer, language, voice variant, rate, speech length limit and coarticulation.
// options.voice is LANGUAGE, LANGUAGE+VARIANT or +VARIANT ("fr", "fr+f3", "+m3").
void set_speech(fml::FmlOptions& fml, const ConvertOptions& options);

// The same settings for the readers that speak as BML does (BML, SMIL-Agent), with the behaviour
// limit (--max-runs) and the frames the document will be rendered at.
bml::BmlOptions bml_options(const ConvertOptions& options);

}  // namespace fapc::pipeline
