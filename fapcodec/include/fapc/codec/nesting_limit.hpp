// The one depth limit of every recursive reader (docs/security.md, "Depth limits"): nested
// parentheses of an Algebra expression, Mimic groups (with their macros expanded), XML elements
// of FML and XMT-Omega, checked before anything recurses so that no input can exhaust the stack.
// libxml2 refuses more than 256 levels on its own; the same number holds everywhere.
#pragma once

#include <string>

#include "fapc/codec/codes.hpp"
#include "fapc/codec/diagnostic.hpp"

namespace fapc {

inline constexpr int kMaxNestingDepth = 256;

// "WHAT nested deeper than 256 levels (the depth limit)", ErrorKind::limit_exceeded.
inline Diagnostic nesting_too_deep(Location where, const std::string& what, std::string source_line = {}) {
  return make_error(codes::limit::nesting_depth, std::move(where),
                    what + " nested deeper than " + std::to_string(kMaxNestingDepth) + " levels (the depth limit)",
                    std::move(source_line));
}

}  // namespace fapc
