// Info: what a file holds, from one read: the frames' summary (kind, fps, duration, the FAPs
// used with their ranges), the reader's facts about the format, and its warnings.
#pragma once

#include <string>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/pipeline/json_value.hpp"

namespace fapc::pipeline {

// {"schema_version", "file", "kind", "name", "fps", "frames", "duration", "faps_used", "faps":
// [{number, name, unit, min, max, frames}], "format": {...facts}, "warnings": [diagnostics]}:
// the `info --json` document of docs/json.md.
// `limits`: the resource limits of the read (docs/security.md); `kind`: the input's kind whatever
// its name (--from), empty: from the extension.
Result<JsonValue> describe(const std::string& path, const Limits& limits = {}, const std::string& kind = {});

}  // namespace fapc::pipeline
