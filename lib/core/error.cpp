#include "core/error.hpp"

#include "core/error_detail.hpp"
#include "core/input_name.hpp"

namespace fest {

std::string with_location(const std::string& what, const std::string& where) {
  // The place belongs to the message a person reads, before any library's detail.
  const auto [message, detail] = split_error_detail(what);
  const std::string place = where.empty() || where == "-" ? std::string(standard_input_name) : where;
  return with_error_detail(std::string(message) + " (" + place + ")", detail);
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
