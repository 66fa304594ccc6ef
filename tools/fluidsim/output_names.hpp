#pragma once
// Output names from a pattern with one printf-style integer conversion (%d, %05d).

#include <string>

namespace fest::fluidsim_tool {

// Whether the pattern holds the conversion; throws Status::usage for a malformed pattern.
bool has_index_conversion(const std::string& pattern);
// The pattern with the conversion replaced by `index` ("%%" -> "%").
std::string expand_pattern(const std::string& pattern, long index);

}  // namespace fest::fluidsim_tool
