// ASCII .fap files: a tolerant reader for every variant found in real files, and a writer of the
// one form every known player reads. See docs/fap-files.md.
#pragma once

#include <functional>
#include <optional>
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
  std::string version;           // header's first token, e.g. "2.1"
  std::string header_name;       // everything between version and fps, joined by single spaces
  double header_fps = 0;         // as written (may be fractional)
  long long header_count = -1;   // as written; -1 when there is no header
  Location header_fps_at;        // where the header's frame rate is written
  bool crlf = false;             // V1
  bool trailing_spaces = false;  // V2
  bool final_newline = true;     // V3 when false
  int comment_lines = 0;         // V4, V5
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
  // Frame k's value line (1-based): where a later stage places what it finds wrong with a frame.
  std::vector<int> value_lines;
};

// `file` names the input in diagnostics. Bytes are taken as Latin-1. `progress`: as for
// scan_fap_text below.
Result<FapReadResult> read_fap_text(std::string_view text, const std::string& file, const FapReadOptions& options = {},
                                    const std::function<void(std::size_t)>& progress = {});

// Frames one at a time, for inputs too long to hold as frames (an error stops the reading).
using FapFrameSink = std::function<Status(const FapFrame&)>;

struct FapScanResult {
  FapReadResult read;  // its sequence has no frames: they went to the sink
  // Frame k's number as read_fap_text would give it. The sink sees the numbers as the file writes
  // them: what they mean (millisecond stamps, frames from 1) is known only at the end of the file.
  std::vector<std::int64_t> numbers;
};

// The reader of read_fap_text, with the same checks, diagnostics and facts, handing each frame to
// `sink` instead of keeping it: 12 bytes a frame are kept (its number and line). `progress`, when
// given, is told now and then how many bytes of `text` are read and will not be looked at again
// unless for a diagnostic (a caller reading a mapped file lets those pages go).
Result<FapScanResult> scan_fap_text(std::string_view text, const std::string& file, const FapReadOptions& options,
                                    const FapFrameSink& sink, const std::function<void(std::size_t)>& progress = {});

// The .fap layouts of the player families (docs/fap-files.md, "Flavours"): each writes exactly
// the header, mask width, FAP 1/2 form, separators and line ends that family's reader expects.
enum class FapFlavour {
  safe,        // what every reader takes: `2.1` header, 68-token masks, FAP 1/2 as 4/6 fields
  xface,       // Xface 1.0: as safe (4/6 fields, frame numbers 0..n-1 index its rows)
  greta_cpp,   // Greta's C++ ReadFapFile: as safe (integers, 4/6 fields, exactly n frames)
  greta_java,  // Greta's Java reader: 69-token masks (last 0), FAP 1/2 as one value each
  vreng,       // VREng 2.0: single spaces only, 68-token masks, FAP 1/2 as one value each
  semaine,     // SEMAINE messages: no header, a time line, frame numbers in milliseconds,
               //   FAP 1/2 as one value each
};

// "safe", "xface", "greta-cpp", "greta-java", "vreng", "semaine": the names options take.
std::string_view fap_flavour_name(FapFlavour flavour);
// The flavour with that name; empty when there is none.
std::optional<FapFlavour> fap_flavour_named(std::string_view name);
// Every name, separated by '|' ("safe|xface|..."), for usage messages.
std::string fap_flavour_names();

struct FapWriteOptions {
  bool trailing_space = true;  // end mask and value lines with one space, as real files do
  bool renumber = true;        // frame numbers 0..n-1; false keeps the sequence's numbers
                               // (the safe flavour only: every other reader needs 0..n-1)
  FapFlavour flavour = FapFlavour::safe;
};

// `sequence` in options.flavour. Fails (ErrorKind::unsupported, naming the frame) where the
// flavour cannot carry it: a viseme or expression other than one select shown alone (blend or
// intensity 63, the rest 0) in a flavour with one value for FAP 1/2; a frame rate that is not a
// whole number of milliseconds per frame in the SEMAINE flavour. Nothing is dropped.
Result<std::string> write_fap_flavour(const FapSequence& sequence, const FapWriteOptions& options = {});

// The safe form, which carries every sequence: `2.1 <name> <fps> <n>`, 68-token masks, FAP 1/2
// with all their fields (4 and 6 values: the reference codec, Xface 1.0 and Greta's C++ reader),
// integer values, LF line ends. options.flavour is not used.
std::string write_fap_text(const FapSequence& sequence, const FapWriteOptions& options = {});

// The .fap writer frame by frame, for sequences too long to hold: the text of write_fap_flavour,
// in pieces. The header needs the frame count, so the caller says what the whole sequence holds
// (how many frames, the first and last numbers). A frame's text is made when the next frame
// comes (a gap is filled by repeating the frame before it) or at finish.
class FapTextWriter {
 public:
  FapTextWriter(const std::string& name, int fps, std::size_t frames, std::int64_t first_number,
                std::int64_t last_number, const FapWriteOptions& options = {});
  ~FapTextWriter();
  // The header; fails when the flavour cannot carry the frame rate.
  Status begin(std::string& out);
  // Fails (nothing appended) when the flavour cannot carry the frame.
  Status add(const FapFrame& frame, std::string& out);
  void finish(std::string& out);

 private:
  void write_pending(std::int64_t next_number, std::string& out);
  FapWriteOptions options_;
  int fps_;
  std::int64_t first_;
  bool renumber_ = true;
  long long count_ = 0;
  std::string name_;
  std::optional<FapFrame> pending_;
};

// The header name written for `name`: one token (whitespace replaced by '_'), below 128 chars.
std::string safe_header_name(std::string_view name);

}  // namespace fapc
