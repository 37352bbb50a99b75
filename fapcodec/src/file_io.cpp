#include "fapc/codec/file_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

namespace fapc {

namespace {

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// The system's reason by generic_category (strerror_r underneath): strerror may fill a buffer
// shared by every thread, and the batch reads and writes on several.
Diagnostic io_error(const std::string& path, const std::string& what) {
  return make_error(ErrorKind::io, Location{path, 0, 0, -1}, what + ": " + std::generic_category().message(errno));
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

 private:
  int fd_;
};

}  // namespace

bool is_gzip(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

Result<std::string> gunzip(std::string_view bytes, const std::string& file, const Limits& limits) {
  // The most bytes this input may inflate to; checked before each chunk is appended.
  const double by_ratio = std::max(static_cast<double>(kExpansionFloor),
                                   limits.max_expansion * static_cast<double>(bytes.size()));
  const bool ratio_binds = by_ratio < static_cast<double>(limits.max_decompressed_bytes);
  const auto allowed = static_cast<std::size_t>(ratio_binds ? by_ratio : static_cast<double>(limits.max_decompressed_bytes));
  z_stream z{};
  if (inflateInit2(&z, 15 + 32) != Z_OK)  // +32: accept gzip and zlib headers
    return make_error(Location::binary(file, 0), "cannot start the gzip decoder");
  std::string out;
  char buffer[65536];
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    z.next_out = reinterpret_cast<Bytef*>(buffer);
    z.avail_out = sizeof buffer;
    rc = inflate(&z, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      const auto offset = static_cast<std::int64_t>(z.total_in);
      const std::string why = z.msg ? z.msg : (rc == Z_BUF_ERROR ? "truncated gzip data" : "bad gzip data");
      inflateEnd(&z);
      return make_error(Location::binary(file, offset), "gzip: " + why);
    }
    const std::size_t produced = sizeof buffer - z.avail_out;
    if (out.size() + produced > allowed) {
      const auto offset = static_cast<std::int64_t>(z.total_in);
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
  const Location whole_file{path, 0, 0, -1};
  // The type is checked before opening (opening a device can have effects of its own) and again
  // on the open descriptor, in case the name changed in between. O_NONBLOCK: opening a FIFO
  // without a writer would otherwise wait forever.
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) {
    if (const char* why = not_readable_type(info.st_mode)) return make_error(ErrorKind::io, whole_file, why);
  }
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
  if (file.get() < 0) return io_error(path, "cannot open file");
  if (::fstat(file.get(), &info) != 0) return io_error(path, "cannot read file");
  if (const char* why = not_readable_type(info.st_mode)) return make_error(ErrorKind::io, whole_file, why);
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const ssize_t got = ::read(file.get(), buffer, sizeof buffer);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      return io_error(path, "cannot read file");
    }
    bytes.append(buffer, static_cast<std::size_t>(got));
  }
  if (is_gzip(bytes)) return gunzip(bytes, path, limits);
  return bytes;
}

Status write_file_atomic(const std::string& path, std::string_view bytes) {
  std::string data;
  if (ends_with(path, ".gz")) {
    data = gzip(bytes);
    bytes = data;
  }
  const auto slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash);
  std::random_device seed;
  const std::string temp =
      folder + "/.fapc-tmp-" + std::to_string(seed()) + "-" +
      (slash == std::string::npos ? path : path.substr(slash + 1));
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) return io_error(path, "cannot create output");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      std::remove(temp.c_str());
      return io_error(path, "cannot write output");
    }
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const Diagnostic error = io_error(path, "cannot replace output");
    std::remove(temp.c_str());
    return error;
  }
  return ok_status();
}

}  // namespace fapc
