// What a tracker's CSV became: frames on the --fps grid and the warnings of the reading.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/fap_sequence.hpp"
#include "fapc/codec/limits.hpp"

namespace fapc::pipeline::bridges {

inline constexpr double kRadiansToAu = 1e5;  // FAP rotations are in 1e-5 rad

struct TrackRead {
  FapSequence frames;
  Diagnostics warnings;
};

struct TrackOptions {
  int fps = 25;
  Limits limits;
};

// A warning at the header naming the columns a reader does not use: nothing is dropped silently.
// `names` in the file's order; the message lists the first few and the count.
Diagnostic columns_not_read(const std::string& file, WarningCode code, const std::vector<std::string>& names,
                            std::string_view why);

}  // namespace fapc::pipeline::bridges
