#include "core/error.hpp"

namespace fest {

std::string with_location(const std::string& what, const std::string& where) {
  if (where.empty() || where == "-") return what + " (standard input)";
  return what + " (" + where + ")";
}

const char* status_name(Status s) noexcept {
  switch (s) {
    case Status::ok: return "ok";
    case Status::failure: return "failure";
    case Status::usage: return "usage";
    case Status::bad_input: return "bad_input";
    case Status::io: return "io";
    case Status::device_not_found: return "device_not_found";
    case Status::device_error: return "device_error";
    case Status::timeout: return "timeout";
    case Status::permission: return "permission";
  }
  return "unknown";
}

}  // namespace fest
