#pragma once
// The sRGB transfer function (IEC 61966-2-1) between linear light and display values in [0,1].

#include <algorithm>
#include <cmath>

namespace fest {

inline double linear_to_srgb(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

inline double srgb_to_linear(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

}  // namespace fest
