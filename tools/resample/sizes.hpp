#pragma once
// "WxH" sizes and target sizes derived from flags, checked against the 2^31-pixel limit
// (and the machine's memory) before any image is allocated.

#include <string>
#include <utility>

namespace fest::resample_tool {

// A target size computed from flags (in double, so that --scale 1e308 does not wrap):
// each side rounded, at least 1, W·H ≤ 2^31 pixels and within this machine's memory, else
// a usage error naming `what` and the limit.
std::pair<int, int> checked_size(double w, double h, const char* what);

// "WxH" -> (W, H); both positive and W·H ≤ 2^31, else a usage error naming `what`.
std::pair<int, int> parse_size(const std::string& text, const char* what);

}  // namespace fest::resample_tool
