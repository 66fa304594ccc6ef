#include "sampling/srgb.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace fest::sampling {

float srgb_to_linear(float c) {
  const double x = c;
  return static_cast<float>(x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4));
}

float linear_to_srgb(float l) {
  const double x = l;
  return static_cast<float>(x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055);
}

const float* srgb8_table() {
  static const auto table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[static_cast<std::size_t>(i)] = srgb_to_linear(static_cast<float>(i / 255.0));
    return t;
  }();
  return table.data();
}

const float* srgb16_table() {
  static const auto table = [] {
    std::vector<float> t(65536);
    for (int i = 0; i < 65536; ++i) t[static_cast<std::size_t>(i)] = srgb_to_linear(static_cast<float>(i / 65535.0));
    return t;
  }();
  return table.data();
}

float srgb8_to_linear(std::uint8_t code) { return srgb8_table()[code]; }
float srgb16_to_linear(std::uint16_t code) { return srgb16_table()[code]; }

}  // namespace fest::sampling
