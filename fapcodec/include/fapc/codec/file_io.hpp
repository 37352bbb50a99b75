// Whole-file I/O shared by every reader and writer: gzip through zlib, and atomic replacement so
// that a failed run never leaves a partial output behind.
#pragma once

#include <string>
#include <string_view>

#include "fapc/codec/diagnostic.hpp"

namespace fapc {

// The file's bytes; a gzip stream (by its magic bytes) is inflated transparently. Every reader
// and every include opens files through here. Errors (ErrorKind::io, for the whole file): "is a
// directory", "not a regular file (a FIFO)" and the like, checked before reading so that a FIFO
// never blocks; "cannot open file: Permission denied" and other errors of the system.
Result<std::string> read_file_bytes(const std::string& path);

bool is_gzip(std::string_view bytes);
Result<std::string> gunzip(std::string_view bytes, const std::string& file);
std::string gzip(std::string_view bytes);

// Writes to a temporary file in the target's folder, then renames it over the target.
// A path ending in ".gz" is compressed first.
Status write_file_atomic(const std::string& path, std::string_view bytes);

}  // namespace fapc
