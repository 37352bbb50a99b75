// What `talk` says, as MPEG-4 visemes in time (docs/fml.md, "talk"): text through a letter-to-viseme
// approximation (the fallback when fapc is built without its speech engine), or phoneme timings from an MBROLA .pho
// file through the standard's phoneme-to-viseme table. Times are seconds from the talk's start.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/transcoder/speech.hpp"

namespace fapc::xmt {

using fapc::VisemeSpan;

struct Speech {
  std::vector<VisemeSpan> visemes;  // in time order, not overlapping
  double duration = 0;              // of the whole utterance, pauses included
};

// One slot of 1/rate seconds per letter group: a doubled letter and the digraphs th, sh, ch, ph,
// ng, ck, qu count once; a letter without a mouth shape of its own (h) joins the previous slot;
// a space is one silent slot, punctuation (. , ; : ! ?) two. Other characters (digits, symbols,
// non-ASCII) are silent slots too, and listed in `skipped` so the caller can say so.
Speech visemes_from_text(std::string_view text, double visemes_per_second, std::string& skipped);

// MBROLA .pho: per line `phoneme duration_ms [position% pitch_Hz]...`; `;` starts a comment.
// Phonemes in SAMPA are mapped with the viseme table of ISO/IEC 14496-2 (Annex C); `_` and `#`
// are silence. Errors at file:line:col; unknown phonemes are warnings (once each) and silent.
Result<Speech> visemes_from_pho(std::string_view text, const std::string& file_name, Diagnostics& warnings);

// The viseme of one SAMPA phoneme; 0 for silence, -1 when unknown.
int viseme_of_phoneme(std::string_view phoneme);

}  // namespace fapc::xmt
