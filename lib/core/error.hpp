#pragma once
// The one error type of fest and its mapping to exit statuses (README "Conventions": 0 ok, 1 failure, 2 usage, 3 bad input, 4 I/O, 5-8 devices).
// Every library throws fest::Error; tools turn it into a one-line message and the status.

#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

namespace fest {

// Exit statuses shared by every tool. The numbers are part of the interface.
enum class Status : int {
  ok = 0,
  failure = 1,          // ran, but the answer is "no" (no convergence, not within tolerance)
  usage = 2,            // unknown flag, bad value
  bad_input = 3,        // unreadable, malformed or unsupported data
  io = 4,               // cannot open, read or write a file
  device_not_found = 5,
  device_error = 6,
  timeout = 7,
  permission = 8,
};

class Error : public std::runtime_error {
 public:
  Error(Status status, std::string message)
      : std::runtime_error(std::move(message)), status_(status) {}
  Status status() const noexcept { return status_; }
  int exit_code() const noexcept { return static_cast<int>(status_); }

 private:
  Status status_;
};

// Short constructors: `throw bad_input("PLY header: {} vertices in {} bytes", n, size);`
template <typename... Args>
Error make_error(Status s, fmt::format_string<Args...> f, Args&&... args) {
  return Error(s, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
Error bad_input(fmt::format_string<Args...> f, Args&&... args) {
  return Error(Status::bad_input, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
Error usage_error(fmt::format_string<Args...> f, Args&&... args) {
  return Error(Status::usage, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
Error io_error(fmt::format_string<Args...> f, Args&&... args) {
  return Error(Status::io, fmt::format(f, std::forward<Args>(args)...));
}
template <typename... Args>
Error runtime_failure(fmt::format_string<Args...> f, Args&&... args) {
  return Error(Status::failure, fmt::format(f, std::forward<Args>(args)...));
}

// "what went wrong (where)" as the design wants it, e.g. "truncated data (bunny.ply)".
std::string with_location(const std::string& what, const std::string& where);

// Status name for reports ("bad_input").
const char* status_name(Status s) noexcept;

}  // namespace fest
