#pragma once
// A full disk for the duration of a scope, imitated by a limit on the size of any file this process
// writes (RLIMIT_FSIZE): a write past it fails with EFBIG, as one on a full disk fails with ENOSPC
// (SIGXFSZ, which would end the process, is ignored meanwhile). Each test runs in its own process
// (gtest_discover_tests), so no other test writes under the limit.
#include <sys/resource.h>

#include <csignal>

namespace flotsam::test {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &old_);
    old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = old_;
    limited.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, old_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit old_{};
  void (*old_handler_)(int) = nullptr;
};

}  // namespace flotsam::test
