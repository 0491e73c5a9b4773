#pragma once
// A full disk, for as long as it lives: files of this process cannot grow beyond `bytes` (writes
// fail with EFBIG instead of the signal that would end the process). Restores both on the way
// out, a failed ASSERT included. ctest runs each test in a process of its own.

#include <sys/resource.h>

#include <csignal>
#include <stdexcept>

namespace ballsight::test {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) : handler_(std::signal(SIGXFSZ, SIG_IGN)) {
    if (getrlimit(RLIMIT_FSIZE, &previous_) != 0) throw std::runtime_error("getrlimit");
    rlimit limit = previous_;
    limit.rlim_cur = bytes;
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) throw std::runtime_error("setrlimit");
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  void (*handler_)(int);
  rlimit previous_{};
};

}  // namespace ballsight::test
