#pragma once
// Synthetic exposure series with a known camera (docs/hdrmerge.md §6): a radiance map
// spanning 4 decades, a gamma-1/2.2 response, Gaussian read noise, 8-bit rounding.

#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

#include "hdr/stack.hpp"

namespace fest::hdr::testing {

// E(x, y) = 10^(-2 + 4 u(x, y)) with u a ramp in x plus a small ripple in y, per channel
// scaled by 1, 0.8, 0.6 so that the channels differ.
inline cv::Mat synthetic_radiance(int width, int height, int channels) {
  cv::Mat e(height, width, CV_32FC(channels));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double u = (x + 0.5) / width + 0.05 * std::sin(6.283185307179586 * y / height);
      for (int c = 0; c < channels; ++c)
        e.ptr<float>(y)[x * channels + c] = float(std::pow(10.0, -2.0 + 4.0 * std::min(1.0, std::max(0.0, u))) *
                                                  (1.0 - 0.2 * c));
    }
  return e;
}

// The camera: Z = round(255 (E dt)^(1/2.2) + noise), clamped to 0..255.
inline cv::Mat expose(const cv::Mat& radiance, double time, double noise_dn, cv::RNG& rng) {
  cv::Mat z(radiance.size(), CV_8UC(radiance.channels()));
  const std::size_t n = radiance.total() * std::size_t(radiance.channels());
  const float* e = radiance.ptr<float>();
  std::uint8_t* out = z.ptr<std::uint8_t>();
  for (std::size_t i = 0; i < n; ++i) {
    const double v = 255.0 * std::pow(std::min(1.0, double(e[i]) * time), 1 / 2.2) + rng.gaussian(noise_dn);
    out[i] = std::uint8_t(std::lround(std::min(255.0, std::max(0.0, v))));
  }
  return z;
}

// True ln f^-1(z) of that camera, normalised like the recovered curve (g(128) = 0).
inline double true_log_inverse(int z) { return 2.2 * std::log(z / 128.0); }

// 12 exposures, 1 ms .. 2.048 s in 1-stop steps.
inline ExposureStack bracket(const cv::Mat& radiance, double noise_dn = 0.5, int count = 12, unsigned seed = 7) {
  ExposureStack s;
  cv::RNG rng(seed);
  for (int k = 0; k < count; ++k) {
    s.times.push_back(0.001 * std::pow(2.0, k));
    s.images.push_back(expose(radiance, s.times.back(), noise_dn, rng));
  }
  return s;
}

}  // namespace fest::hdr::testing
