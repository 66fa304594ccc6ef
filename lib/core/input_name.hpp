#pragma once
// How every message names standard input (given as "-" on the command line): one spelling
// for all tools -- "standard input", never "stdin" or "<stdin>".

#include <string>

namespace fest {

inline constexpr const char* standard_input_name = "standard input";

// The name messages give an input: standard_input_name for "-" or "", else the path.
std::string input_name(const std::string& path);

}  // namespace fest
