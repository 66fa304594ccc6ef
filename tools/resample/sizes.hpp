#pragma once
// "WxH" sizes and dimensions from the command line, checked against the 2^31-pixel limit.

#include <string>
#include <utility>

namespace fest::resample_tool {

// A dimension in [1, 2^31]: usage error naming `what` otherwise.
int checked_dimension(long long v, const char* what);

// "WxH" -> (W, H); both positive and W·H ≤ 2^31, else a usage error naming `what`.
std::pair<int, int> parse_size(const std::string& text, const char* what);

}  // namespace fest::resample_tool
