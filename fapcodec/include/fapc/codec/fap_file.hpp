// ASCII .fap files: a tolerant reader for every variant found in real files, and a writer of the
// one form every known player reads. See docs/fap-files.md.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/codec/limits.hpp"

namespace fapc {

// What the reader saw: the variant of the format and its deviations from the baseline layout.
struct FapFileFacts {
  bool has_header = false;
  std::string version;        // header's first token, e.g. "2.1"
  std::string header_name;    // everything between version and fps, joined by single spaces
  double header_fps = 0;      // as written (may be fractional)
  long long header_count = -1;  // as written; -1 when there is no header
  bool crlf = false;                 // V1
  bool trailing_spaces = false;      // V2
  bool final_newline = true;         // V3 when false
  int comment_lines = 0;             // V4, V5
  bool utf8_bom = false;
  bool tabs = false;                 // V14
  bool mask_69_tokens = false;       // V8
  bool fap12_single_values = false;  // V9: FAP 1/2 as one value each
  bool fap12_full_fields = false;    // V10: FAP 1/2 as 4/6 values
  bool semaine_time_line = false;    // V12: a leading bare number
  bool millisecond_stamps = false;   // V12: frame numbers are ms on a constant step
  bool frames_from_one = false;      // V15
  bool float_values = false;         // V17
  bool zero_active_faps = false;     // V16 (some frame has an empty mask)
  bool frame_gaps = false;           // numbering not contiguous after normalisation

  // A short name of the variant ("Xface", "Greta", "VREng 2.0", "SEMAINE", ...).
  std::string variant() const;
  // The deviations from the baseline form, one short phrase each, for `fapc info`.
  std::vector<std::string> deviations() const;
};

struct FapReadOptions {
  // VREng's private convention for version 2.0 files: divide every value by 20.
  bool vreng_divide_v20 = false;
  // fps to assume for header-less files numbered 0, 1, 2, ... (Greta's rate).
  int headerless_fps = 25;
  // The most frames the file may span from its first frame to its last, gaps included (writers
  // fill gaps; see Limits::max_frames).
  std::int64_t max_frames = Limits{}.max_frames;
};

struct FapReadResult {
  FapSequence sequence;
  FapFileFacts facts;
  Diagnostics warnings;
};

// `file` names the input in diagnostics. Bytes are taken as Latin-1.
Result<FapReadResult> read_fap_text(std::string_view text, const std::string& file,
                                    const FapReadOptions& options = {});

// FAP 1 and FAP 2 are always written with all their fields (4 and 6 values), the form the
// reference codec, Xface 1.0 and Greta's C++ reader expect; see docs/fap-files.md.
struct FapWriteOptions {
  bool trailing_space = true;  // end mask and value lines with one space, as real files do
  bool renumber = true;        // frame numbers 0..n-1; false keeps the sequence's numbers
};

// The safe form: `2.1 <name> <fps> <n>`, 68-token masks, integer values, LF line ends.
std::string write_fap_text(const FapSequence& sequence, const FapWriteOptions& options = {});

// The header name written for `name`: one token (whitespace replaced by '_'), below 128 chars.
std::string safe_header_name(std::string_view name);

}  // namespace fapc
