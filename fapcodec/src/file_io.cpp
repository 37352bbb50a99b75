#include "fapc/codec/file_io.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <system_error>
#include <utility>

#include "fapc/codec/codes.hpp"

namespace fapc {

namespace {

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// The system's reason by generic_category (strerror_r underneath): strerror may fill a buffer
// shared by every thread, and the batch reads and writes on several.
Diagnostic io_error(ErrorCode code, const std::string& path, const std::string& what) {
  return make_error(code, Location::whole_file(path), what + ": " + std::generic_category().message(errno));
}

// Why a file of this type cannot be read as an input, or nullptr for a regular file.
const char* not_readable_type(mode_t mode) {
  if (S_ISREG(mode)) return nullptr;
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "not a regular file (a FIFO)";
  if (S_ISSOCK(mode)) return "not a regular file (a socket)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "not a regular file (a device)";
  return "not a regular file";
}

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

// Opens an input for reading, or says why not; `info` receives its status. The type is checked
// before opening (opening a device can have effects of its own) and again on the open
// descriptor, in case the name changed in between. O_NONBLOCK: opening a FIFO without a writer
// would otherwise wait forever.
Result<int> open_input(const std::string& path, struct stat& info) {
  const Location whole_file = Location::whole_file(path);
  if (::stat(path.c_str(), &info) == 0) {
    if (const char* why = not_readable_type(info.st_mode)) return make_error(codes::io::not_a_file, whole_file, why);
  }
  Descriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (file.get() < 0) return io_error(codes::io::cannot_open, path, "cannot open file");
  if (::fstat(file.get(), &info) != 0) return io_error(codes::io::cannot_read, path, "cannot read file");
  if (const char* why = not_readable_type(info.st_mode)) return make_error(codes::io::not_a_file, whole_file, why);
  return file.release();
}

// A name for the temporary file of one output: unique among this process's outputs (a counter),
// and among processes (the process id, and a random number drawn once per process in case ids
// are reused: building a std::random_device for every output cost 5 % of a batch). Safe to call
// from several threads.
// "<pid>-<seed>-": the seed tells this process from an earlier one that had the same pid.
std::string process_part() {
  static const std::uint32_t process_seed = std::random_device{}();
  return std::to_string(::getpid()) + "-" + std::to_string(process_seed) + "-";
}

std::string temporary_name() {
  static std::atomic<std::uint64_t> counter{0};
  return process_part() + std::to_string(counter.fetch_add(1, std::memory_order_relaxed));
}

}  // namespace

std::string own_temporary_prefix() { return ".fapc-tmp-" + process_part(); }

bool is_gzip(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

Result<std::string> gunzip(std::string_view bytes, const std::string& file, const Limits& limits) {
  // The most bytes this input may inflate to; checked before each chunk is appended.
  const double by_ratio =
      std::max(static_cast<double>(kExpansionFloor), limits.max_expansion * static_cast<double>(bytes.size()));
  const bool ratio_binds = by_ratio < static_cast<double>(limits.max_decompressed_bytes);
  const auto allowed =
      static_cast<std::size_t>(ratio_binds ? by_ratio : static_cast<double>(limits.max_decompressed_bytes));
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK)  // +32: accept gzip and zlib headers
    return make_error(codes::gzip::bad_data, Location::binary(file, 0), "cannot start the gzip decoder");
  std::string out;
  char buffer[65536];
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  int rc = Z_OK;
  for (;;) {
    if (rc == Z_STREAM_END) {
      // gzip allows members one after the other (RFC 1952 2.2; zcat reads them all): read each
      // under the same limits. Anything else after a member is refused rather than ignored.
      if (z.avail_in == 0) break;
      const auto offset = static_cast<std::int64_t>(bytes.size() - z.avail_in);
      if (!is_gzip(bytes.substr(static_cast<std::size_t>(offset)))) {
        inflateEnd(&z);
        return make_error(codes::gzip::trailing_bytes, Location::binary(file, offset),
                          "gzip: " + std::to_string(z.avail_in) + " bytes after the end of the gzip data");
      }
      inflateReset(&z);
    }
    z.next_out = reinterpret_cast<Bytef*>(buffer);
    z.avail_out = sizeof buffer;
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      const auto offset = static_cast<std::int64_t>(bytes.size() - z.avail_in);
      const std::string why = z.msg ? z.msg : (rc == Z_BUF_ERROR ? "truncated gzip data" : "bad gzip data");
      inflateEnd(&z);
      return make_error(codes::gzip::bad_data, Location::binary(file, offset), "gzip: " + why);
    }
    const std::size_t produced = sizeof buffer - z.avail_out;
    if (out.size() + produced > allowed) {
      const auto offset = static_cast<std::int64_t>(bytes.size() - z.avail_in);
      inflateEnd(&z);
      return limit_error(Location::binary(file, offset),
                         "gzip data inflates to more than " + std::to_string(allowed) + " bytes",
                         ratio_binds ? Limit::expansion : Limit::decompressed_bytes, limits);
    }
    out.append(buffer, produced);
  }
  inflateEnd(&z);
  return out;
}

std::string gzip(std::string_view bytes) {
  z_stream z{};
  deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY);  // +16: gzip
  std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

Result<std::string> read_file_bytes(const std::string& path, const Limits& limits) {
  struct stat info {};
  auto opened = open_input(path, info);
  if (!opened) return opened.error();
  const Descriptor file(*opened);
  // Read straight into the string, sized by the file's length plus one byte, which sees the end
  // of the file: one allocation and no copy unless the file grows while it is read.
  std::string bytes;
  std::size_t used = 0;
  bytes.resize(static_cast<std::size_t>(std::max<off_t>(info.st_size, 0)) + 1);
  for (;;) {
    if (used == bytes.size()) bytes.resize(std::max(bytes.size() * 2, used + (std::size_t{1} << 20)));
    const ssize_t got = ::read(file.get(), bytes.data() + used, bytes.size() - used);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      return io_error(codes::io::cannot_read, path, "cannot read file");
    }
    used += static_cast<std::size_t>(got);
  }
  bytes.resize(used);
  if (is_gzip(bytes)) return gunzip(bytes, path, limits);
  return bytes;
}

Result<MappedFile> MappedFile::open(const std::string& path) {
  struct stat info {};
  auto opened = open_input(path, info);
  if (!opened) return opened.error();
  const Descriptor file(*opened);
  const auto size = static_cast<std::size_t>(info.st_size);
  if (size == 0) return MappedFile(nullptr, 0);
  void* data = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, file.get(), 0);
  if (data == MAP_FAILED) return io_error(codes::io::cannot_read, path, "cannot read file");
  ::madvise(data, size, MADV_SEQUENTIAL);
  return MappedFile(static_cast<const char*>(data), size);
}

MappedFile::MappedFile(MappedFile&& other) noexcept : data_(other.data_), size_(other.size_) {
  other.data_ = nullptr;
  other.size_ = 0;
}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  std::swap(data_, other.data_);
  std::swap(size_, other.size_);
  return *this;
}

MappedFile::~MappedFile() {
  if (data_) ::munmap(const_cast<char*>(data_), size_);
}

void MappedFile::release(std::size_t offset) const {
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const std::size_t end = std::min(offset, size_) / page * page;
  if (data_ && end > 0) ::madvise(const_cast<char*>(data_), end, MADV_DONTNEED);
}

Result<SourceText> SourceText::open(const std::string& path, const Limits& limits) {
  Result<MappedFile> mapped = MappedFile::open(path);
  if (!mapped) return mapped.error();
  SourceText text;
  if (is_gzip(mapped->bytes())) {
    Result<std::string> inflated = gunzip(mapped->bytes(), path, limits);
    if (!inflated) return inflated.error();
    text.read_ = std::move(*inflated);
  } else {
    text.mapped_ = std::move(*mapped);
  }
  return text;
}

namespace {

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string temporary_path(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return folder_of(path) + "/.fapc-tmp-" + temporary_name() + "-" +
         (slash == std::string::npos ? path : path.substr(slash + 1));
}

// A file without a name in `folder` (O_TMPFILE; a named file removed at once where the file
// system has no unnamed ones), open for reading and writing, or -1.
int open_unnamed(const std::string& folder) {
  int fd = -1;
#ifdef O_TMPFILE
  fd = ::open(folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
#endif
  if (fd < 0) {
    const std::string temp = folder + "/.fapc-tmp-" + temporary_name();
    fd = ::open(temp.c_str(), O_CREAT | O_EXCL | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd >= 0) ::unlink(temp.c_str());
  }
  return fd;
}

// Where an output bound for a device or a FIFO waits until it is whole: the temporary folder
// ($TMPDIR), not the device's folder (/dev is no place for files).
std::string scratch_folder_for(const std::string& output) {
  auto target = output_target(output);
  if (!target || target->way == OutputTarget::Way::replace) return folder_of(output);
  std::error_code ignored;
  const std::string temp = std::filesystem::temp_directory_path(ignored).string();
  return temp.empty() ? "/tmp" : temp;
}

Status write_whole(int fd, std::string_view bytes, const std::string& path) {
  while (!bytes.empty()) {
    const ssize_t put = ::write(fd, bytes.data(), bytes.size());
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return io_error(codes::io::cannot_write_output, path, "cannot write output");
    bytes.remove_prefix(static_cast<std::size_t>(put));
  }
  return ok_status();
}

// Opens a device or FIFO output for writing: never created, never truncated (neither means
// anything there), and checked again on the open descriptor in case the name changed since it
// was looked at. Opening a FIFO waits for its reader, as the shell's `>` does.
Result<int> open_stream(const std::string& path, const std::string& file) {
  Descriptor out(::open(file.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC));
  if (out.get() < 0) return io_error(codes::io::cannot_create_output, path, "cannot open output");
  struct stat info {};
  if (::fstat(out.get(), &info) != 0) return io_error(codes::io::cannot_create_output, path, "cannot open output");
  if (!S_ISCHR(info.st_mode) && !S_ISFIFO(info.st_mode))
    return make_error(codes::io::output_changed, Location::whole_file(path),
                      "is no longer a character device or a FIFO; nothing written");
  return out.release();
}

// Before the rename: the name must still hold a regular file, or nothing (it may have been
// replaced by something else while the output was made).
Status still_replaceable(const std::string& path, const std::string& file) {
  struct stat info {};
  if (::lstat(file.c_str(), &info) == 0 && !S_ISREG(info.st_mode))
    return make_error(codes::io::output_changed, Location::whole_file(path),
                      "is no longer a regular file; nothing written");
  return ok_status();
}

}  // namespace

Result<AtomicFile> AtomicFile::create(const std::string& path) {
  auto target = output_target(path);
  if (!target) return target.error();
  if (target->way == OutputTarget::Way::stream) {
    const int fd = open_unnamed(scratch_folder_for(path));
    std::FILE* file = fd < 0 ? nullptr : ::fdopen(fd, "w+");
    if (!file) {
      if (fd >= 0) ::close(fd);
      return io_error(codes::io::cannot_create_output, path, "cannot create output");
    }
    return AtomicFile(path, std::move(*target), std::string(), file);
  }
  std::string temp = temporary_path(target->file);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
  if (fd < 0) return io_error(codes::io::cannot_create_output, path, "cannot create output");
  // A file replaced keeps its permissions: a private output stays private.
  struct stat existing {};
  if (::stat(target->file.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)) ::fchmod(fd, existing.st_mode & 0777);
  std::FILE* file = ::fdopen(fd, "wb");
  if (!file) {
    ::close(fd);
    std::remove(temp.c_str());
    return io_error(codes::io::cannot_create_output, path, "cannot create output");
  }
  return AtomicFile(path, std::move(*target), std::move(temp), file);
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      temp_(std::move(other.temp_)),
      file_(other.file_) {
  other.file_ = nullptr;
}

AtomicFile::~AtomicFile() {
  if (!file_) return;
  std::fclose(file_);
  if (!temp_.empty()) std::remove(temp_.c_str());
}

Status AtomicFile::write(std::string_view bytes) {
  if (!file_ || std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    return io_error(codes::io::cannot_write_output, path_, "cannot write output");
  return ok_status();
}

Status AtomicFile::commit() {
  if (!file_) return io_error(codes::io::cannot_write_output, path_, "cannot write output");
  if (target_.way == OutputTarget::Way::stream) return commit_to_stream();
  const bool flushed = std::fflush(file_) == 0 && !std::ferror(file_);
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    const Diagnostic error = io_error(codes::io::cannot_write_output, path_, "cannot write output");
    std::remove(temp_.c_str());
    return error;
  }
  if (auto replaceable = still_replaceable(path_, target_.file); !replaceable) {
    std::remove(temp_.c_str());
    return replaceable;
  }
  if (std::rename(temp_.c_str(), target_.file.c_str()) != 0) {
    const Diagnostic error = io_error(codes::io::cannot_replace_output, path_, "cannot replace output");
    std::remove(temp_.c_str());
    return error;
  }
  return ok_status();
}

// The whole output, from its scratch file to the device or FIFO, now that nothing can fail
// before it is complete.
Status AtomicFile::commit_to_stream() {
  std::FILE* scratch = std::exchange(file_, nullptr);
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> closing(scratch, &std::fclose);
  if (std::fflush(scratch) != 0 || std::ferror(scratch) || std::fseek(scratch, 0, SEEK_SET) != 0)
    return io_error(codes::io::cannot_write_output, path_, "cannot write output");
  auto opened = open_stream(path_, target_.file);
  if (!opened) return opened.error();
  const Descriptor out(*opened);
  std::string buffer(std::size_t{1} << 20, '\0');
  for (;;) {
    const std::size_t got = std::fread(buffer.data(), 1, buffer.size(), scratch);
    if (got > 0)
      if (auto written = write_whole(out.get(), {buffer.data(), got}, path_); !written) return written;
    if (got < buffer.size()) break;
  }
  if (std::ferror(scratch)) return io_error(codes::io::cannot_write_output, path_, "cannot write output");
  return ok_status();
}

Status write_file_atomic(const std::string& path, std::string_view bytes) {
  std::string data;
  if (ends_with(path, ".gz")) {
    data = gzip(bytes);
    bytes = data;
  }
  // A device or FIFO takes the bytes, already whole, directly.
  auto target = output_target(path);
  if (!target) return target.error();
  if (target->way == OutputTarget::Way::stream) {
    auto opened = open_stream(path, target->file);
    if (!opened) return opened.error();
    const Descriptor out(*opened);
    return write_whole(out.get(), bytes, path);
  }
  auto file = AtomicFile::create(path);
  if (!file) return file.error();
  if (auto written = file->write(bytes); !written) return written;
  return file->commit();
}

Result<ScratchFile> ScratchFile::create(const std::string& output) {
  const int fd = open_unnamed(scratch_folder_for(output));
  if (fd < 0) return io_error(codes::io::cannot_create_output, output, "cannot create output");
  std::FILE* file = ::fdopen(fd, "w+");
  if (!file) {
    ::close(fd);
    return io_error(codes::io::cannot_create_output, output, "cannot create output");
  }
  return ScratchFile(output, file);
}

ScratchFile::ScratchFile(ScratchFile&& other) noexcept : output_(std::move(other.output_)), file_(other.file_) {
  other.file_ = nullptr;
}

ScratchFile::~ScratchFile() {
  if (file_) std::fclose(file_);
}

Status ScratchFile::write(std::string_view bytes) {
  if (!file_ || std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    return io_error(codes::io::cannot_write_output, output_, "cannot write output");
  return ok_status();
}

Status ScratchFile::read_back(const std::function<Status(std::string_view)>& sink) {
  if (!file_ || std::fflush(file_) != 0 || std::fseek(file_, 0, SEEK_SET) != 0)
    return io_error(codes::io::cannot_write_output, output_, "cannot write output");
  std::string buffer(std::size_t{1} << 20, '\0');
  for (;;) {
    const std::size_t got = std::fread(buffer.data(), 1, buffer.size(), file_);
    if (got > 0)
      if (auto status = sink({buffer.data(), got}); !status) return status;
    if (got < buffer.size()) break;
  }
  if (std::ferror(file_)) return io_error(codes::io::cannot_write_output, output_, "cannot write output");
  return ok_status();
}

}  // namespace fapc
