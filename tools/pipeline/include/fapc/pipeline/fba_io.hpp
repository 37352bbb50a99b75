// FBA streams in files: reading a .fba, encoding with the conversion options (and checking when
// asked), packing coded planes into MP4 samples, and an .mp4's FBA track decoded.
#pragma once

#include <optional>
#include <string>

#include "fapc/codec/fba.hpp"
#include "fapc/mpeg4/fba_track.hpp"
#include "fapc/mpeg4/mp4_reader.hpp"
#include "fapc/pipeline/loaded.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::pipeline {

// --quant, --intra-period, --ranges and --masks as the encoder's options.
FbaEncodeOptions fba_encode_options(const ConvertOptions& options);

// Reads and decodes a .fba file (gzip inflated transparently).
Result<DecodedFba> read_fba_file(const std::string& path, const Limits& limits = {});

// Why frames at `fps` cannot be coded (the rate takes 8 bits), placed where the input wrote the
// rate (`rate_at`, when it wrote `rate_written` there) or else on `input`; nothing when they can.
std::optional<Diagnostic> fba_rate_error(int fps, const Location& rate_at, int rate_written, const std::string& input);

// FbaEncodeOptions::locate for frames read from lines: frame `numbers[k]` (ascending) was read at
// line `lines[k]` of `input`. Empty when the two do not match (frames not read from lines). The
// three are referred to, not copied: they must outlive the encoder.
std::function<Location(std::int64_t, int)> frame_locator(const std::vector<std::int64_t>& numbers,
                                                         const std::vector<int>& lines, const std::string& input);

// Encodes the frames of `loaded`, which came from `input`: errors name the input (a frame rate
// the stream cannot code, the place the input wrote it). With options.verify, the stream is
// decoded and checked too (ErrorKind::verification_failed when it does not match).
Result<EncodedFba> encode_checked(const Loaded& loaded, const ConvertOptions& options, const std::string& input,
                                  bool align_planes = false);

// The MP4 FBA track of an encoding made with align_planes: each plane, started by its start
// code and byte-aligned, becomes one sample lasting the frames it covers (timescale = fps).
xmt::FbaTrackInput pack_fba_track(const EncodedFba& encoded, int fps);
// The same track as views into `encoded`, which must outlive it (no copy of each plane).
xmt::FbaTrackView fba_track_view(const EncodedFba& encoded, int fps);

// An .mp4's FBA track and what it decodes to. Errors inside the track point at the byte in the
// .mp4 ("FBA track sample N"); decoded.warnings holds the container's warnings, then the
// decoder's.
struct Mp4Fba {
  xmt::FbaTrackInput track;
  DecodedFba decoded;
};
Result<Mp4Fba> read_mp4_fba(const std::string& path, const Limits& limits = {});
Result<Mp4Fba> decode_mp4_fba(const xmt::Mp4File& mp4, const std::string& path, const Limits& limits = {});

}  // namespace fapc::pipeline
