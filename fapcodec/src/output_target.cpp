#include "fapc/codec/output_target.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <memory>

#include "fapc/codec/codes.hpp"

namespace fapc {

namespace {

constexpr const char* kWhatTakesOutput = " (an output is written to a file, a character device or a FIFO)";

Diagnostic refused(const std::string& path, const std::string& why) {
  return make_error(codes::io::output_refused, Location::whole_file(path), why);
}

// Why a file of this type takes no output, or nullptr when it does.
const char* refused_type(mode_t mode) {
  if (S_ISREG(mode) || S_ISCHR(mode) || S_ISFIFO(mode)) return nullptr;
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISBLK(mode)) return "is a block device";
  if (S_ISSOCK(mode)) return "is a socket";
  return "is not a file";
}

// `path` with every symbolic link resolved, or `path` itself when that fails (the writer's own
// error will then say why).
std::string resolved(const std::string& path) {
  const std::unique_ptr<char, decltype(&std::free)> real(::realpath(path.c_str(), nullptr), &std::free);
  return real ? std::string(real.get()) : path;
}

}  // namespace

Result<OutputTarget> output_target(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    // Nothing behind the name: a new file, unless the name is a link to nothing, which would
    // create a file wherever the link points.
    struct stat link {};
    if (errno == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
      char target[PATH_MAX];
      const ssize_t length = ::readlink(path.c_str(), target, sizeof target - 1);
      const std::string to = length > 0 ? std::string(target, static_cast<std::size_t>(length)) : std::string("?");
      return refused(path,
                     "is a symbolic link to '" + to + "', which does not exist (fapc creates no file through a link)");
    }
    return OutputTarget{OutputTarget::Way::replace, path};
  }
  if (const char* why = refused_type(info.st_mode)) return refused(path, std::string(why) + kWhatTakesOutput);
  if (S_ISREG(info.st_mode)) return OutputTarget{OutputTarget::Way::replace, resolved(path)};
  return OutputTarget{OutputTarget::Way::stream, path};
}

Status check_output_path(const std::string& path) {
  if (path == "-") return ok_status();
  auto target = output_target(path);
  if (!target) return target.error();
  return ok_status();
}

}  // namespace fapc
