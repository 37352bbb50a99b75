// What the FBA parts of the program share: options from the command line to the encoder's, and
// reading a .fba file with diagnostics that name it.
#pragma once

#include <string>

#include "fapc/codec/fba.hpp"
#include "fapc/registry.hpp"

namespace fapc::cli {

// Reads and decodes a .fba file (gzip inflated transparently).
Result<DecodedFba> read_fba_file(const std::string& path);

// Encodes `sequence`, which came from `input`: errors name the input. With options.verify, the
// stream is decoded and checked too (a failure's message starts with "verification failed").
Result<EncodedFba> encode_checked(const FapSequence& sequence, const ConvertOptions& options, const std::string& input,
                                  bool align_planes = false);

}  // namespace fapc::cli
