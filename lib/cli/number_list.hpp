#pragma once
// Comma-separated numbers on the command line ("--size 852,567", "--angles 0,30,60"):
// parsed once, in main.cpp, into the typed options, so that no command re-parses a string.
// Errors are usage errors (exit 2) that name the flag. Include only from tools/*/main.cpp
// (or the tool's own option helpers).

#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace fest::cli {

// Numbers separated by `sep`; between min and max of them (max 0 = no upper bound);
// each finite. "flag" is the option's name for the message.
inline std::vector<double> number_list(std::string_view text, std::size_t min, std::size_t max,
                                       std::string_view flag, char sep = ',') {
  std::vector<double> values;
  const std::string s(text);
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = s.find(sep, begin);
    const std::string item = s.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    char* stop = nullptr;
    const double x = std::strtod(item.c_str(), &stop);
    if (item.empty() || *stop || !std::isfinite(x))
      throw usage_error("{} takes numbers separated by '{}', not '{}'", flag, sep, s);
    values.push_back(x);
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  if (values.size() < min || (max != 0 && values.size() > max)) {
    const std::string count = min == max ? std::to_string(min)
                              : max == 0 ? "at least " + std::to_string(min)
                                         : std::to_string(min) + " to " + std::to_string(max);
    throw usage_error("{} takes {} numbers, got {} ('{}')", flag, count, values.size(), s);
  }
  return values;
}

// The same for whole numbers: each value must be an integer within [lo, hi].
inline std::vector<long long> integer_list(std::string_view text, std::size_t min, std::size_t max,
                                           std::string_view flag, long long lo, long long hi,
                                           char sep = ',') {
  std::vector<long long> out;
  for (const double x : number_list(text, min, max, flag, sep)) {
    if (x != std::floor(x) || x < static_cast<double>(lo) || x > static_cast<double>(hi))
      throw usage_error("{} takes whole numbers in {}..{}, not '{}'", flag, lo, hi, std::string(text));
    out.push_back(static_cast<long long>(x));
  }
  return out;
}

}  // namespace fest::cli
