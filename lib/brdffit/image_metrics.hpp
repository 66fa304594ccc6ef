#pragma once
// Photograph vs re-rendering (docs/brdffit.md §6, `eval`, chapter Fig. 8.17): errors
// of linear radiance inside the mask and PSNR of the tone-mapped images.

#include <opencv2/core.hpp>

namespace fest::brdffit {

struct RenderError {
  double rmse = 0;          // sqrt(mean over mask pixels and channels of (P - R)^2)
  double relative_l2 = 0;   // ||P - R|| / ||P|| over mask pixels and channels
  double psnr_db = 0;       // of the tone-mapped images (peak 1), infinite when equal
  double exposure = 0;      // the tone-mapping scale used (1 / 99th percentile of P)
  long pixels = 0;          // mask pixels compared (finite in both images)
  cv::Mat error;            // |P - R| per channel, CV_32FC3, zero outside the mask
};

// Tone mapping for the PSNR: x -> sRGB(clamp(exposure x, 0, 1)) with one exposure for both
// images, chosen from the photograph. Throws fest::Error (bad_input) on size mismatch or
// an empty mask.
RenderError compare_renderings(const cv::Mat& photo, const cv::Mat& rendering, const cv::Mat& mask);

}  // namespace fest::brdffit
