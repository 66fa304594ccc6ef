#include "brdffit/image_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/error_stats.hpp"
#include "core/srgb.hpp"

namespace fest::brdffit {

RenderError compare_renderings(const cv::Mat& photo, const cv::Mat& rendering, const cv::Mat& mask) {
  if (photo.size() != rendering.size())
    throw bad_input("the photograph is {}x{} but the rendering is {}x{}", photo.cols, photo.rows, rendering.cols,
                    rendering.rows);
  if (!mask.empty() && mask.size() != photo.size())
    throw bad_input("the mask is {}x{} but the images are {}x{}", mask.cols, mask.rows, photo.cols, photo.rows);
  if (photo.type() != CV_32FC3 || rendering.type() != CV_32FC3) throw bad_input("both images must be float RGB");
  RenderError e;
  e.error = cv::Mat(photo.size(), CV_32FC3, cv::Scalar::all(0));
  std::vector<float> luminance;
  auto inside = [&](int x, int y) {
    if (!mask.empty() && mask.at<std::uint8_t>(y, x) == 0) return false;
    const cv::Vec3f &p = photo.at<cv::Vec3f>(y, x), &r = rendering.at<cv::Vec3f>(y, x);
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(p[c]) || !std::isfinite(r[c])) return false;
    return true;
  };
  for (int y = 0; y < photo.rows; ++y)
    for (int x = 0; x < photo.cols; ++x)
      if (inside(x, y)) {
        const cv::Vec3f& p = photo.at<cv::Vec3f>(y, x);
        luminance.push_back(std::max({p[0], p[1], p[2]}));
      }
  if (luminance.empty()) throw bad_input("no finite pixel inside the mask");
  const std::size_t q = std::min(luminance.size() - 1, static_cast<std::size_t>(0.99 * luminance.size()));
  std::nth_element(luminance.begin(), luminance.begin() + static_cast<long>(q), luminance.end());
  e.exposure = luminance[q] > 0 ? 1.0 / luminance[q] : 1.0;
  // Linear radiance differences, photo energy, tone-mapped differences.
  ErrorAccumulator linear, tone_mapped;
  double sp = 0;
  for (int y = 0; y < photo.rows; ++y)
    for (int x = 0; x < photo.cols; ++x) {
      if (!inside(x, y)) continue;
      ++e.pixels;
      const cv::Vec3f &p = photo.at<cv::Vec3f>(y, x), &r = rendering.at<cv::Vec3f>(y, x);
      cv::Vec3f& err = e.error.at<cv::Vec3f>(y, x);
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(static_cast<double>(p[c]) - r[c]);
        linear.add(d);
        sp += static_cast<double>(p[c]) * p[c];
        tone_mapped.add(std::abs(linear_to_srgb(e.exposure * p[c]) - linear_to_srgb(e.exposure * r[c])));
        err[c] = static_cast<float>(d);
      }
    }
  e.rmse = linear.rmse();
  e.relative_l2 = sp > 0 ? std::sqrt(linear.sum_sq / sp) : std::sqrt(linear.sum_sq);
  e.psnr_db = tone_mapped.psnr(1.0);
  return e;
}

}  // namespace fest::brdffit
