// What an output path names, and so how an output is written there (docs/security.md, "Outputs"):
// a regular file (or nothing yet) is replaced whole by renaming a finished temporary file over it;
// a character device or a FIFO is written directly, once the output is complete, as standard
// output is; anything else is refused before any work. Only a regular file is ever renamed over.
#pragma once

#include <string>

#include "fapc/codec/diagnostic.hpp"

namespace fapc {

struct OutputTarget {
  enum class Way {
    replace,  // a regular file, or a name with nothing behind it yet: a temporary file renamed over it
    stream,   // a character device or a FIFO: opened and written, never created, renamed or truncated
  };
  Way way = Way::replace;
  // The file to replace, symbolic links resolved (the link stays, its file is replaced), or the
  // device or FIFO to write to.
  std::string file;
};

// Where `path` sends an output, or why it cannot take one (ErrorKind::io, naming `path`): a
// directory, a block device, a socket, or a symbolic link whose file does not exist. A name that
// cannot be looked at (a missing folder, no permission) is left to the writer, whose error says so.
Result<OutputTarget> output_target(const std::string& path);

// Whether an output can go to `path`, asked before the work so that a refused output costs
// nothing; the writers ask again when they write (the file system may have changed since).
// Standard output ("-") always can.
Status check_output_path(const std::string& path);

}  // namespace fapc
