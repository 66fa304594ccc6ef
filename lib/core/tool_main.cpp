#include "core/tool_main.hpp"

#include <cstdio>
#include <exception>
#include <new>

#include <string>

#include "core/error.hpp"
#include "core/error_detail.hpp"
#include "core/quote.hpp"

namespace fest {

namespace {

bool details_shown = false;

void print_error(const std::string& tool, const char* what) {
  std::fflush(stdout);
  const auto [message, detail] = split_error_detail(what);
  std::fprintf(stderr, "%s: error: %.*s\n", tool.c_str(), static_cast<int>(message.size()), message.data());
  if (details_shown && !detail.empty())
    std::fprintf(stderr, "%s: detail: %s\n", tool.c_str(), quoted_bytes(detail, 400).c_str());
}

}  // namespace

void show_error_details(bool on) { details_shown = on; }

int run_tool(const std::string& tool, const std::function<int()>& body) {
  try {
    return body();
  } catch (const Error& e) {
    print_error(tool, e.what());
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    print_error(tool, "out of memory");
    return static_cast<int>(Status::failure);
  } catch (const std::exception& e) {
    // A library exception that escaped its wrapper: treat as bad input, since every
    // such path so far was triggered by data the library could not parse.
    print_error(tool, e.what());
    return static_cast<int>(Status::bad_input);
  }
}

void warn(const std::string& tool, const std::string& message) {
  std::fprintf(stderr, "%s: warning: %s\n", tool.c_str(), message.c_str());
}

}  // namespace fest
