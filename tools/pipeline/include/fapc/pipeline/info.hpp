// Info: what a file holds, from one read: the frames' summary (kind, fps, duration, the FAPs
// used with their ranges), the reader's facts about the format, and its warnings.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::pipeline {

// {"file", "kind", "name", "fps", "frames", "duration", "faps used", "faps": [{number, name, unit,
// min, max, frames}], "format": {...facts}, "warnings": ["FILE:...: warning: ..."]}.
Result<nlohmann::ordered_json> describe(const std::string& path);

}  // namespace fapc::pipeline
