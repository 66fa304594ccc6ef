#include "sizes.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <fmt/format.h>

#include "core/resources.hpp"
#include "core/error.hpp"

namespace fest::resample_tool {

namespace {

constexpr double kMaxPixels = 2147483648.0;  // 2^31
// A float RGBA pixel of the output: the most a pixel of the resized image costs.
constexpr double kBytesPerPixel = 16;

// "400000x400000 pixels", or words where a side is beyond every number.
std::string size_text(double w, double h) {
  if (!std::isfinite(w) || !std::isfinite(h)) return "more than 1e308 pixels a side";
  return fmt::format("{:.6g}x{:.6g} pixels", w, h);
}

}  // namespace

std::pair<int, int> checked_size(double w, double h, const char* what) {
  w = std::round(w);
  h = std::round(h);
  if (!(w >= 1 && h >= 1))
    throw fest::usage_error("{} gives an image of {}: each side must be at least 1 pixel", what, size_text(w, h));
  if (!(w * h <= kMaxPixels))
    throw fest::usage_error("{} gives an image of {}: more than the 2147483648 (2^31) pixels an image may have", what,
                            size_text(w, h));
  check_fits_in_memory(w * h * kBytesPerPixel,
                            fmt::format("{} gives a {:.0f}x{:.0f} image, which at 16 bytes a pixel", what, w, h));
  return {static_cast<int>(w), static_cast<int>(h)};
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
