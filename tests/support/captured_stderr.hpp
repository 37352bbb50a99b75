// This process's standard error (file descriptor 2) sent to a temporary file while the object
// lives, for tests that check a library prints nothing: what was written is read back by take().
#pragma once

#include <unistd.h>

#include <cstdio>
#include <string>

namespace fapc::test {

class CapturedStderr {
 public:
  CapturedStderr() : file_(std::tmpfile()), saved_(::dup(STDERR_FILENO)) {
    std::fflush(stderr);
    if (file_ != nullptr) ::dup2(::fileno(file_), STDERR_FILENO);
  }
  ~CapturedStderr() { restore(); }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;

  // Everything written since construction; standard error goes back to where it went before.
  std::string take() {
    restore();
    std::string out;
    if (file_ == nullptr) return out;
    std::rewind(file_);
    char block[4096];
    for (std::size_t n; (n = std::fread(block, 1, sizeof block, file_)) > 0;) out.append(block, n);
    std::fclose(file_);
    file_ = nullptr;
    return out;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
  }
  std::FILE* file_;
  int saved_;
};

}  // namespace fapc::test
