// What the FBA parts of the program share: options from the command line to the encoder's, and
// reading a .fba file with diagnostics that name it.
#pragma once

#include <string>

#include "fapc/codec/fba.hpp"
#include "fapc/registry.hpp"
#include "fapc/mpeg4/fba_track.hpp"

namespace fapc::cli {

// Reads and decodes a .fba file (gzip inflated transparently).
Result<DecodedFba> read_fba_file(const std::string& path);

// Encodes `sequence`, which came from `input`: errors name the input. With options.verify, the
// stream is decoded and checked too (a failure's message starts with "verification failed").
Result<EncodedFba> encode_checked(const FapSequence& sequence, const ConvertOptions& options, const std::string& input,
                                  bool align_planes = false);

// An .mp4's FBA track and what it decodes to (format_mp4.cpp). Errors inside the track point at
// the byte in the .mp4 ("FBA track sample N"); decoded.warnings holds the container's warnings,
// then the decoder's.
struct Mp4Fba {
  xmt::FbaTrackInput track;
  DecodedFba decoded;
};
Result<Mp4Fba> read_mp4_fba(const std::string& path);

}  // namespace fapc::cli
