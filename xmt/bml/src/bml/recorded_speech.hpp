// Recorded speech (the NVBG/SmartBody dialect, docs/bml.md "SmartBody"): a speech whose
// <description type="audio/..."> names an audio file is not synthesised. Its marks carry their
// own times (<sync id="T3" time="0.34"/>, seconds from the speech's start); its audio is the file
// next to the document (`<file ref="NAME"/>`, NAME.wav), read under the include rules.
#pragma once

#include <string>
#include <vector>

#include "bml/bml_model.hpp"
#include "fapc/bml/bml.hpp"
#include "fapc/xml/xml_document.hpp"

namespace fapc::bml {

// The description child of `speech` that names audio (type "audio/..."), or null.
const xmlNode* audio_description(const xml::XmlDocument& doc, const xmlNode* speech);

// The speech as recorded: marks at their times, length the last mark's (or the audio's, when
// longer), the audio when the file exists. A missing file is a warning (bml.recorded_audio_missing)
// at the file element; a file the include rules refuse, too large or not a WAV fapc reads is an
// error. Paths read are added to `recordings`.
Result<SpokenText> recorded_speech(const xml::XmlDocument& doc, const xmlNode* speech, const xmlNode* description,
                                   const ReaderOptions& options, Diagnostics& warnings,
                                   std::vector<std::string>& recordings);

}  // namespace fapc::bml
