// The conversion options shared by compile, batch, plot, combine, encode and verify: from the
// command line to fapc::pipeline::ConvertOptions.
#pragma once

#include <set>
#include <string>

#include "fapc/args.hpp"
#include "fapc/pipeline/options.hpp"

namespace fapc::cli {

using pipeline::ConvertOptions;
using pipeline::PictureSettings;

inline const std::set<std::string> kConvertValued = {"fps", "profile", "event", "quant",
                                                      "intra-period", "ranges", "masks", "from", "to",
                                                      "duration", "speech-rate", "voice", "fap-flavour",
                                                      "allow-include", "max-frames", "max-runs",
                                                      "max-decompressed-bytes", "max-expansion",
                                                      "size", "frame-rate", "frame", "time", "sheet"};
// The resource limits (docs/security.md), taken by every command that reads inputs.
inline const std::set<std::string> kLimitValued = {"max-frames", "max-runs", "max-decompressed-bytes",
                                                    "max-expansion"};
// `names` plus the limit options.
inline std::set<std::string> with_limits(std::set<std::string> names) {
  names.insert(kLimitValued.begin(), kLimitValued.end());
  return names;
}
inline const std::set<std::string> kConvertFlags = {"strict", "verify", "points"};

// Reads the shared options; sets args' error on bad values.
ConvertOptions convert_options(Args& args);

}  // namespace fapc::cli
