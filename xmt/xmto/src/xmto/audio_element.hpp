// `audio src="x.wav"`: a recording placed on the timeline, and, when `x.pho` lies beside it, the
// visemes of its phonemes timed with it (docs/xmt-omega.md, "Recordings").
#pragma once

#include <optional>
#include <string>

#include "fapc/xml/xml_document.hpp"
#include "fapc/xmto/xmto.hpp"

namespace fapc::xmt {

struct Recording {
  std::string wav_path;                 // as resolved
  std::optional<std::string> pho_path;  // the .pho beside it, when there is one
  Timeline timeline;                    // from 0: the sound, the visemes; end: its length
};

// Errors at the element or its src/clipEnd attribute: no src, a URL, a path outside the allowed
// folders, a file that cannot be read or is larger than options.max_audio_bytes (checked before
// reading), a WAV other than 16-bit PCM. A malformed .pho is an error at its own file:line:col.
Result<Recording> load_recording(const xml::XmlDocument& doc, const xmlNode* element, const XmtoOptions& options,
                                 Diagnostics& warnings);

}  // namespace fapc::xmt
