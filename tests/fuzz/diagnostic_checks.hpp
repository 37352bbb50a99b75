// The diagnostics contract (docs/cli.md) as the fuzz targets check it: every error names the
// input it is about and a place in it, a line and column for text or a byte offset for binary
// input. A diagnostic without them is a bug the fuzzer should stop on, like a crash.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fapc/codec/diagnostic.hpp"

namespace fapc::fuzz {

inline bool is_placed(const Diagnostic& d) {
  return !d.where.file.empty() && (d.where.line > 0 || d.where.byte_offset >= 0);
}

// An unplaced diagnostic stops the run like a crash (there is no switch to look past one).
inline void require_placed(const Diagnostic& d) {
  if (is_placed(d)) return;
  std::fprintf(stderr, "unplaced diagnostic: %s\n", format_diagnostic(d).c_str());
  std::abort();
}

}  // namespace fapc::fuzz
