#pragma once
// A simulated camera for exposure series with a known response (docs/hdrmerge.md §5):
//   Z = round(255 min(1, E dt)^(1/gamma) + n),  n ~ N(0, noise_dn^2),  clamped to 0..255.
// Used to bracket real HDR content (EXR environment maps) into 8-bit exposures whose
// true response is known, for tests and for the benchmark against OpenCV.

#include <cstdint>

#include <opencv2/core.hpp>

namespace fest::hdr {

struct CameraModel {
  double gamma = 2.2;     // f(X) = 255 X^(1/gamma)
  double noise_dn = 0.5;  // read noise, standard deviation in digital numbers
};

// radiance: CV_32FC1 or CV_32FC3; negative values count as 0. Deterministic for a given
// seed. Throws bad_input for other depths and non-finite radiance, usage_error for a bad
// model or time.
cv::Mat expose(const cv::Mat& radiance, double time, const CameraModel& camera, std::uint64_t seed);

// ln f^-1(z) of the model, normalised like a recovered response (g(128) = 0); z >= 1.
double model_log_inverse(const CameraModel& camera, int z);

}  // namespace fest::hdr
