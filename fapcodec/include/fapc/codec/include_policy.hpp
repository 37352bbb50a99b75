// Which files a script may include (docs/security.md, "Includes"). Scripts come from other people:
// a Mimic defxpr, an XMT-Omega `animation src`, an FML talk file or a .combine operand must not
// read any file on the machine (and echo it in a diagnostic). Every include mechanism resolves
// its names through resolve_include.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fapc/codec/diagnostic.hpp"

namespace fapc {

// Inputs that include inputs nest at most this deep (a .combine operand that is a .combine, an
// XMT-Omega animation of an XMT-Omega document...).
inline constexpr std::size_t kMaxIncludeDepth = 16;

struct IncludePolicy {
  // Folders whose trees includes may read. Empty: the including file's own folder. The command
  // line puts the top input's folder here, then every --allow-include DIR.
  std::vector<std::string> allowed_folders;
  // Where relative names start. Empty: the including file's folder. Set for a script read from
  // standard input (its names start in the working folder).
  std::string base_folder;
};

// The path to read for `name`, written at `where` in `including_file`: relative names start at
// the base folder; the result, with symbolic links and ".." resolved, must lie inside one of the
// allowed folders. Errors (ErrorKind::bad_input, at `where`) say which folders are allowed and
// that --allow-include adds more.
Result<std::string> resolve_include(std::string_view name, const std::string& including_file,
                                    const IncludePolicy& policy, const Location& where);

}  // namespace fapc
