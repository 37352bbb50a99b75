#include "forked_call.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <exception>

namespace fapc::speech {
namespace {

// Both ends of a pipe, closed when it goes out of scope; close-on-exec so that no program another
// thread starts inherits them (and keeps them open past the child's end).
struct Pipe {
  int read = -1;
  int write = -1;
  bool open() {
    int ends[2];
    if (::pipe2(ends, O_CLOEXEC) != 0) return false;
    read = ends[0];
    write = ends[1];
    return true;
  }
  static void close_end(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
  ~Pipe() {
    close_end(read);
    close_end(write);
  }
};

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

[[noreturn]] void run_child(const std::function<std::string()>& work, int output, int messages) {
  // Standard error is unbuffered: the engine's fprintf(stderr) lands in the pipe at once. Buffered
  // standard output may hold bytes of the parent's; they are never flushed here (_exit).
  if (::dup2(messages, STDERR_FILENO) < 0 || ::dup2(messages, STDOUT_FILENO) < 0) ::_exit(3);
  int status = 0;
  try {
    const std::string result = work();
    if (!write_all(output, result.data(), result.size())) status = 4;
  } catch (...) {  // std::bad_alloc: the parent reports the child's failure
    status = 5;
  }
  ::_exit(status);
}

// Appends what `fd` has to `into` (up to `limit`, counting the rest in `dropped`); false at its end.
bool drain(int fd, std::string& into, std::size_t limit, std::size_t& dropped) {
  char block[65536];
  const ssize_t n = ::read(fd, block, sizeof block);
  if (n < 0) return errno == EINTR || errno == EAGAIN;
  if (n == 0) return false;
  const std::size_t got = static_cast<std::size_t>(n);
  const std::size_t kept = into.size() < limit ? std::min(got, limit - into.size()) : 0;
  into.append(block, kept);
  dropped += got - kept;
  return true;
}

}  // namespace

ForkedOutcome call_in_child(const std::function<std::string()>& work, std::size_t max_output,
                            std::size_t max_messages) {
  ForkedOutcome out;
  Pipe output, messages;
  if (!output.open() || !messages.open()) {
    out.detail = errno;
    return out;
  }
  const pid_t child = ::fork();
  if (child < 0) {
    out.detail = errno;
    return out;
  }
  if (child == 0) {
    // Without the read ends, a child writing past what the parent reads gets SIGPIPE once the
    // parent stops reading, instead of waiting for ever.
    Pipe::close_end(output.read);
    Pipe::close_end(messages.read);
    run_child(work, output.write, messages.write);
  }
  Pipe::close_end(output.write);
  Pipe::close_end(messages.write);

  // Both pipes read together: a child blocked writing one while the parent waits on the other
  // would never end.
  std::size_t output_dropped = 0;
  pollfd fds[2] = {{output.read, POLLIN, 0}, {messages.read, POLLIN, 0}};
  while (fds[0].fd >= 0 || fds[1].fd >= 0) {
    if (::poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    if (fds[0].fd >= 0 && fds[0].revents != 0 && !drain(fds[0].fd, out.output, max_output, output_dropped))
      fds[0].fd = -1;
    if (fds[1].fd >= 0 && fds[1].revents != 0 && !drain(fds[1].fd, out.messages, max_messages, out.messages_dropped))
      fds[1].fd = -1;
    // A child that writes past the bound is not waited for: it ends when its pipe closes.
    if (output_dropped > 0) break;
  }
  Pipe::close_end(output.read);
  Pipe::close_end(messages.read);

  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (output_dropped > 0) {
    out.end = ForkedOutcome::End::too_large;
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    out.end = ForkedOutcome::End::finished;
  } else {
    out.end = ForkedOutcome::End::failed;
    out.detail = WIFSIGNALED(status) ? WTERMSIG(status) : -WEXITSTATUS(status);
  }
  return out;
}

}  // namespace fapc::speech
