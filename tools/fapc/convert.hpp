// The conversion at the heart of `compile` and `batch`: load any input, write any output,
// atomically, reporting warnings (errors under --strict).
#pragma once

#include <string>

#include "fapc/args.hpp"
#include "fapc/registry.hpp"

namespace fapc::cli {

// Option names shared by compile and batch.
inline const std::set<std::string> kConvertValued = {"fps", "profile", "event", "quant",
                                                      "intra-period", "ranges", "masks", "from", "to",
                                                      "duration", "speech-rate", "fap-flavour",
                                                      "allow-include", "size", "frame-rate", "frame",
                                                      "time", "sheet"};
inline const std::set<std::string> kConvertFlags = {"strict", "verify", "points"};

// Reads the shared options; sets args' error on bad values.
ConvertOptions convert_options(Args& args);

struct ConvertOutcome {
  int exit_status = kExitOk;
  Loaded loaded;  // what the input became (for summaries)
};

// Writes `loaded` to `output` (by extension, or `to_kind`), atomically, or `-` for standard output;
// prints diagnostics and returns the exit status.
int write_output(const Loaded& loaded, const std::string& output, const ConvertOptions& options,
                 const std::string& to_kind = {});

// Converts `input` to `output` (by extension, or by `to_kind` when given); prints diagnostics.
ConvertOutcome convert(const std::string& input, const std::string& output,
                       const ConvertOptions& options, const std::string& to_kind = {});

}  // namespace fapc::cli
