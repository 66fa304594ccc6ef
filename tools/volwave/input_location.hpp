#pragma once
// Bad input of a .vw file reported with where it came from (the path, or standard input).

#include <string>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"

namespace fest::volwave_tool {

inline std::string where_of(const std::string& path) { return input_name(path); }

// f(), with a bad-input error's message given the input's location.
template <typename F>
auto named(const std::string& path, F&& f) {
  try {
    return f();
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), where_of(path)));
  }
}

}  // namespace fest::volwave_tool
