#pragma once
// The sRGB transfer function (IEC 61966-2-1) between linear light and display values: the
// one formula of fest. linear_to_srgb / srgb_to_linear clamp to [0, 1] first (display
// values); the *_unclamped forms extend the curve beyond it (the linear segment below 0, the
// power law above 1), for filtering that must carry out-of-range values through a decode
// and encode unchanged (lib/sampling's working images).

#include <algorithm>
#include <cmath>

namespace fest {

inline double linear_to_srgb_unclamped(double v) {
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

inline double srgb_to_linear_unclamped(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

inline double linear_to_srgb(double v) { return linear_to_srgb_unclamped(std::clamp(v, 0.0, 1.0)); }

inline double srgb_to_linear(double v) { return srgb_to_linear_unclamped(std::clamp(v, 0.0, 1.0)); }

}  // namespace fest
