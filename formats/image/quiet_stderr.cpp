#include "formats/image/quiet_stderr.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace fest::formats::image_detail {
namespace {
std::mutex& stderr_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

QuietStderr::QuietStderr() : lock_(stderr_mutex()) {
  std::cerr.flush();
  std::fflush(stderr);
  const int null_fd = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null_fd < 0) return;  // nowhere to send it: let the chatter through
  saved_fd_ = ::dup(STDERR_FILENO);
  if (saved_fd_ >= 0) ::dup2(null_fd, STDERR_FILENO);
  ::close(null_fd);
}

QuietStderr::~QuietStderr() {
  if (saved_fd_ < 0) return;
  std::cerr.flush();
  std::fflush(stderr);
  ::dup2(saved_fd_, STDERR_FILENO);
  ::close(saved_fd_);
}

}  // namespace fest::formats::image_detail
