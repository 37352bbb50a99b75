// Whole-file I/O shared by every reader and writer: gzip through zlib, and atomic replacement so
// that a failed run never leaves a partial output behind.
#pragma once

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "fapc/codec/diagnostic.hpp"
#include "fapc/codec/limits.hpp"
#include "fapc/codec/output_target.hpp"

namespace fapc {

// The file's bytes; a gzip stream (by its magic bytes) is inflated transparently, within the
// limits' decompressed bytes and expansion factor. Every reader and every include opens files
// through here. Errors (ErrorKind::io, for the whole file): "is a directory", "not a regular file
// (a FIFO)" and the like, checked before reading so that a FIFO never blocks; "cannot open file:
// Permission denied" and other errors of the system; limit_exceeded for a gzip bomb.
Result<std::string> read_file_bytes(const std::string& path, const Limits& limits = {});

// A file's bytes mapped into memory, for readers that go through a long input once (or twice)
// without holding it: release() lets the pages already read go, so the process keeps only what
// it is reading (the pages come back from the page cache if looked at again). Opened with the
// checks of read_file_bytes; a gzip file cannot be mapped (the caller reads it whole instead).
class MappedFile {
 public:
  static Result<MappedFile> open(const std::string& path);
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  std::string_view bytes() const { return {data_, size_}; }
  // The pages wholly before byte `offset` are not needed now.
  void release(std::size_t offset) const;

 private:
  MappedFile(const char* data, std::size_t size) : data_(data), size_(size) {}
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

// A text input's bytes for a reader that goes through it front to back: mapped when the file can
// be, so that release() lets the pages already read go (a script of a million elements is some
// 100 MB of text, as much as everything else its compile keeps); read whole when it is gzip,
// where release() does nothing. Views into bytes() stay valid while the object is not moved.
class SourceText {
 public:
  static Result<SourceText> open(const std::string& path, const Limits& limits = {});
  std::string_view bytes() const { return mapped_ ? mapped_->bytes() : std::string_view(read_); }
  void release(std::size_t offset) const {
    if (mapped_) mapped_->release(offset);
  }

 private:
  std::optional<MappedFile> mapped_;
  std::string read_;
};

bool is_gzip(std::string_view bytes);
// Refuses (limit_exceeded, at the compressed byte reached) before the output would pass
// limits.max_decompressed_bytes, or max_expansion times the input's size once past
// kExpansionFloor.
Result<std::string> gunzip(std::string_view bytes, const std::string& file, const Limits& limits = {});
std::string gzip(std::string_view bytes);

// Writes to a temporary file in the target's folder, then renames it over the target; a
// character device or a FIFO is written directly (output_target.hpp says which, and what is
// refused). A path ending in ".gz" is compressed first.
Status write_file_atomic(const std::string& path, std::string_view bytes);

// The start of the names this process gives its temporary outputs (".fapc-tmp-<pid>-<seed>-"):
// a sweep of leftovers from killed runs must pass over these, which other threads may be writing.
std::string own_temporary_prefix();

// The same, in pieces, for outputs too long to hold: the bytes go to a temporary file in the
// target's folder, which commit() renames over the target. Until then the target is untouched,
// and a file never committed is removed (an error found late still leaves nothing). No gzip.
// A device or FIFO target gets the bytes from an unnamed file in the temporary folder when
// commit() is called, so that it too sees a whole output or nothing.
class AtomicFile {
 public:
  static Result<AtomicFile> create(const std::string& path);
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  Status write(std::string_view bytes);
  Status commit();

 private:
  AtomicFile(std::string path, OutputTarget target, std::string temp, std::FILE* file)
      : path_(std::move(path)), target_(std::move(target)), temp_(std::move(temp)), file_(file) {}
  Status commit_to_stream();
  std::string path_;
  OutputTarget target_;
  std::string temp_;           // the file renamed over the target; empty for a device or FIFO
  std::FILE* file_ = nullptr;  // null once committed or moved from
};

// An unnamed file beside an output (in the temporary folder for a device or FIFO), to write and read back: the body of
// an output whose beginning is known only at the end (a .fap header gives the frame count). It never has a name
// (O_TMPFILE; a named file removed at once where the file system has no unnamed ones), so nothing
// is left behind whatever happens. Errors name the output.
class ScratchFile {
 public:
  static Result<ScratchFile> create(const std::string& output);
  ScratchFile(ScratchFile&& other) noexcept;
  ScratchFile& operator=(ScratchFile&&) = delete;
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  ~ScratchFile();

  Status write(std::string_view bytes);
  // Everything written, from the start, in pieces of 1 MB.
  Status read_back(const std::function<Status(std::string_view)>& sink);

 private:
  ScratchFile(std::string output, std::FILE* file) : output_(std::move(output)), file_(file) {}
  std::string output_;
  std::FILE* file_ = nullptr;
};

}  // namespace fapc
