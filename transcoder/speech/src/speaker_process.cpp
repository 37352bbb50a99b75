#include "speaker_process.hpp"

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <fstream>
#include <mutex>
#include <sstream>

namespace fapc::speech {
namespace {

// The speaker trusts its parent (the same program), but a size read from a socket is still checked
// before anything is allocated for it.
constexpr std::uint64_t kMaxFrameBytes = std::uint64_t{1} << 32;

bool send_all(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::send(fd, p, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

bool receive_all(int fd, void* data, std::size_t size) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = ::recv(fd, p, size, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

bool send_number(int fd, std::uint64_t value) { return send_all(fd, &value, sizeof value); }
bool receive_number(int fd, std::uint64_t& value) { return receive_all(fd, &value, sizeof value); }

bool send_bytes(int fd, std::string_view bytes) {
  return send_number(fd, bytes.size()) && send_all(fd, bytes.data(), bytes.size());
}

bool receive_bytes(int fd, std::string& into, std::uint64_t max_size) {
  std::uint64_t size = 0;
  if (!receive_number(fd, size) || size > max_size) return false;
  into.resize(size);
  return receive_all(fd, into.data(), size);
}

// The speaker's life: one request after another until its parent closes the socket.
[[noreturn]] void run_speaker(const SpeakerWork& work, int fd) {
  // It writes nowhere but to the socket: a parent's standard output left open here would keep a
  // reader of that pipe waiting; a closed socket is an error of send(), not a signal.
  const int null = ::open("/dev/null", O_RDWR);
  if (null < 0 || ::dup2(null, STDIN_FILENO) < 0 || ::dup2(null, STDOUT_FILENO) < 0 || ::dup2(null, STDERR_FILENO) < 0)
    ::_exit(3);
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  bool prepared = false;
  for (;;) {
    std::uint64_t max_output = 0, max_messages = 0;
    std::string request;
    if (!receive_number(fd, max_output) || !receive_number(fd, max_messages) ||
        !receive_bytes(fd, request, kMaxFrameBytes))
      ::_exit(0);
    if (!prepared && work.prepare != nullptr) work.prepare();
    prepared = true;
    const ForkedOutcome out = call_in_child([&] { return work.serve(request); }, max_output, max_messages);
    const std::uint64_t head[] = {static_cast<std::uint64_t>(out.end),
                                  static_cast<std::uint64_t>(static_cast<std::int64_t>(out.detail)),
                                  out.messages_dropped};
    if (!send_all(fd, head, sizeof head) || !send_bytes(fd, out.output) || !send_bytes(fd, out.messages)) ::_exit(0);
  }
}

// The speakers started, by the work they serve.
struct Speakers {
  std::mutex mutex;
  struct Entry {
    std::string (*serve)(std::string_view) = nullptr;
    pid_t owner = 0;          // the process that started it
    std::atomic<int> fd{-1};  // the owner's end of the socket; -1 once it failed
  };
  Entry entries[kMaxSpeakers];
  // Under `mutex`. A process forked from the owner (not by a speaker) inherits the table but must
  // not talk on its parent's socket: there, every entry is forgotten.
  Entry* find(const SpeakerWork& work) {
    for (Entry& e : entries) {
      if (e.serve != nullptr && e.owner != ::getpid()) {
        if (e.fd >= 0) ::close(e.fd);
        e.fd = -1;
        e.serve = nullptr;
      }
      if (e.serve == work.serve) return &e;
    }
    return nullptr;
  }
};

Speakers& speakers() {
  static Speakers s;
  return s;
}

}  // namespace

int thread_count() {
  std::ifstream stat("/proc/self/stat");
  std::string line;
  if (!std::getline(stat, line)) return 0;
  // "pid (name) state ppid ...": the name may hold spaces and parentheses, so count from the last
  // ')'. num_threads is the 20th field, the 18th after the name.
  const std::size_t close = line.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream fields(line.substr(close + 1));
  std::string field;
  for (int i = 0; i < 18 && fields >> field; ++i) {
  }
  try {
    return std::stoi(field);
  } catch (...) {
    return 0;
  }
}

SpeakerStart start_speaker(const SpeakerWork& work, bool even_with_threads) {
  Speakers& s = speakers();
  const std::lock_guard lock(s.mutex);
  if (s.find(work) != nullptr) return SpeakerStart::started;
  Speakers::Entry* free = s.find(SpeakerWork{nullptr, nullptr});
  if (free == nullptr) return SpeakerStart::failed;
  if (!even_with_threads && thread_count() > 1) return SpeakerStart::other_threads;
  int ends[2];
  // Close-on-exec: a program this process runs later must not hold the speaker's socket open.
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return SpeakerStart::failed;
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(ends[0]);
    ::close(ends[1]);
    return SpeakerStart::failed;
  }
  if (pid == 0) {
    ::close(ends[0]);
    run_speaker(work, ends[1]);
  }
  ::close(ends[1]);
  free->fd = ends[0];
  free->serve = work.serve;
  free->owner = ::getpid();
  return SpeakerStart::started;
}

ForkedOutcome ask_speaker(const SpeakerWork& work, std::string_view request, std::size_t max_output,
                          std::size_t max_messages) {
  ForkedOutcome out;
  Speakers::Entry* speaker = nullptr;
  {
    const std::lock_guard lock(speakers().mutex);
    speaker = speakers().find(work);
  }
  const int fd = speaker != nullptr ? speaker->fd.load() : -1;
  std::uint64_t head[3] = {};
  if (fd < 0 || !send_number(fd, max_output) || !send_number(fd, max_messages) || !send_bytes(fd, request) ||
      !receive_all(fd, head, sizeof head) || head[0] > static_cast<std::uint64_t>(ForkedOutcome::End::too_large) ||
      !receive_bytes(fd, out.output, max_output) || !receive_bytes(fd, out.messages, max_messages)) {
    // The speaker is gone, or the conversation is out of step: it is not asked again.
    if (fd >= 0 && speaker->fd.exchange(-1) == fd) ::close(fd);
    out.end = ForkedOutcome::End::could_not_start;
    out.detail = ESRCH;
    return out;
  }
  out.end = static_cast<ForkedOutcome::End>(head[0]);
  out.detail = static_cast<int>(static_cast<std::int64_t>(head[1]));
  out.messages_dropped = head[2];
  return out;
}

}  // namespace fapc::speech
