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
#include "fapc/transcoder/frame_budget.hpp"
#include "fapc/transcoder/profile.hpp"
#include "fapc/transcoder/timeline.hpp"

namespace fapc {

struct MimicOptions {
  const Profile* profile = nullptr;  // nullptr: default_profile()
  // Reads an included file (defxpr). Empty: read from disk (read_file_bytes). Tests and fuzzers
  // pass their own.
  std::function<Result<std::string>(const std::string& path)> read_file;
  std::int64_t max_runs = Limits{}.max_runs;  // scheduled runs after repeats (--max-runs)
  // The frames the program will be rendered at: a program too long for them is refused once it
  // is scheduled, before its clips are made (the error FrameStream::start would give). fps 0:
  // unchecked.
  FrameBudget frames;
  // Which files a defxpr may name (docs/security.md); by default the program's own folder tree.
  IncludePolicy includes;
};

struct MimicProgram {
  Timeline timeline;
  Diagnostics warnings;  // range checks and other non-fatal findings, with positions
};

Result<MimicProgram> compile_mimic(std::string_view source, const std::string& file_name,
                                   const MimicOptions& options = {});

}  // namespace fapc
