// The Mimic language (docs/mimic.md): a program
// compiles to the shared timeline. Parse, check, schedule and lower; the first error stops.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/include_policy.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/timeline/timeline.hpp"
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/profile.hpp"
#include "fapc/transcoder/reader_options.hpp"

namespace fapc {

struct MimicProgram {
  Timeline timeline;
  Diagnostics warnings;  // range checks and other non-fatal findings, with positions
};

Result<MimicProgram> compile_mimic(std::string_view source, const std::string& file_name,
                                   const ReaderOptions& options = {});

}  // namespace fapc
