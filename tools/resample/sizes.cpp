#include "sizes.hpp"

#include <cstdint>
#include <cstdlib>

#include "core/error.hpp"

namespace fest::resample_tool {

int checked_dimension(long long v, const char* what) {
  if (v <= 0 || v > (1LL << 31) - 1) throw fest::usage_error("{}: dimension {} is out of range [1, 2^31)", what, v);
  return static_cast<int>(v);
}

std::pair<int, int> parse_size(const std::string& text, const char* what) {
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos || x == 0 || x + 1 == text.size())
    throw fest::usage_error("{}: '{}' is not of the form WxH", what, text);
  char* end = nullptr;
  const std::string ws = text.substr(0, x), hs = text.substr(x + 1);
  const long long w = std::strtoll(ws.c_str(), &end, 10);
  if (*end != '\0') throw fest::usage_error("{}: '{}' is not of the form WxH", what, text);
  const long long h = std::strtoll(hs.c_str(), &end, 10);
  if (*end != '\0') throw fest::usage_error("{}: '{}' is not of the form WxH", what, text);
  if (w <= 0 || h <= 0) throw fest::usage_error("{}: size {} must be positive", what, text);
  if (w > (1LL << 31) || h > (1LL << 31) || w * h > (1LL << 31))
    throw fest::usage_error("{}: size {} exceeds 2^31 pixels", what, text);
  return {static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace fest::resample_tool
