#include "hdr/bracket.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fest::hdr {

cv::Mat expose(const cv::Mat& radiance, double time, const CameraModel& camera, std::uint64_t seed) {
  if (radiance.depth() != CV_32F || (radiance.channels() != 1 && radiance.channels() != 3))
    throw bad_input("bracketing needs a float radiance image with 1 or 3 channels");
  if (!(camera.gamma > 0 && std::isfinite(camera.gamma))) throw usage_error("camera gamma must be positive");
  if (!(camera.noise_dn >= 0 && std::isfinite(camera.noise_dn))) throw usage_error("camera read noise must not be negative");
  if (!(time > 0 && std::isfinite(time))) throw usage_error("exposure time {} must be positive", time);
  const cv::Mat e = radiance.isContinuous() ? radiance : radiance.clone();
  cv::Mat z(e.size(), CV_8UC(e.channels()));
  const std::size_t n = e.total() * std::size_t(e.channels());
  const float* in = e.ptr<float>();
  std::uint8_t* out = z.ptr<std::uint8_t>();
  cv::RNG rng(seed);
  const double inverse_gamma = 1 / camera.gamma;
  for (std::size_t i = 0; i < n; ++i) {
    // Real maps carry small negative values (ringing of their filtering); a sensor sees
    // no negative light, so they expose as 0.
    if (!std::isfinite(in[i])) throw bad_input("radiance value at sample {} is not finite", i);
    const double x = std::max(0.0, double(in[i]));
    const double v = 255.0 * std::pow(std::min(1.0, x * time), inverse_gamma) +
                     (camera.noise_dn > 0 ? rng.gaussian(camera.noise_dn) : 0.0);
    out[i] = std::uint8_t(std::lround(std::clamp(v, 0.0, 255.0)));
  }
  return z;
}

double model_log_inverse(const CameraModel& camera, int z) { return camera.gamma * std::log(z / 128.0); }

}  // namespace fest::hdr
