#include "sampling/image_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/core.hpp>

#include "core/error.hpp"
#include "core/error_stats.hpp"
#include "sampling/scenes.hpp"

namespace fest::sampling {

namespace {

// The image's luminance-free grey value at pixel i: the first channel of grey images,
// the mean of R, G, B for colour (alpha ignored).
double grey(const FloatImage& img, std::size_t pixel) {
  const int c = img.channels;
  const float* p = img.data.data() + pixel * static_cast<std::size_t>(c);
  if (c <= 2) return p[0];
  return (static_cast<double>(p[0]) + p[1] + p[2]) / 3;
}

}  // namespace

ErrorMeasures compare_images(const FloatImage& test, const FloatImage& ref, const std::vector<std::uint8_t>& mask) {
  if (test.width != ref.width || test.height != ref.height || test.channels != ref.channels)
    throw bad_input("metrics: image {}x{}x{} and reference {}x{}x{} differ in size or channels", test.width,
                    test.height, test.channels, ref.width, ref.height, ref.channels);
  const std::size_t pixels = static_cast<std::size_t>(test.width) * static_cast<std::size_t>(test.height);
  if (!mask.empty() && mask.size() != pixels)
    throw bad_input("metrics: the mask has {} pixels, the image {}", mask.size(), pixels);
  ErrorMeasures m;
  ErrorAccumulator errors;
  const auto c = static_cast<std::size_t>(test.channels);
  for (std::size_t p = 0; p < pixels; ++p) {
    if (!mask.empty() && mask[p] == 0) continue;
    ++m.n_pixels;
    for (std::size_t ch = 0; ch < c; ++ch) errors.add(std::fabs(static_cast<double>(test.data[p * c + ch]) - ref.data[p * c + ch]));
  }
  if (errors.n == 0) throw bad_input("metrics: the mask selects no pixel");
  m.maxabs = errors.max_abs;
  m.rmse = errors.rmse();
  m.psnr = errors.psnr(1.0);
  return m;
}

std::vector<double> row_power_spectrum(const FloatImage& img) {
  if (img.width < 2) throw bad_input("power spectrum: the image must be at least 2 pixels wide");
  cv::Mat rows(img.height, img.width, CV_64F);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      rows.at<double>(y, x) = grey(img, static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x));
  cv::Mat spec;
  cv::dft(rows, spec, cv::DFT_ROWS | cv::DFT_COMPLEX_OUTPUT);
  const int n = img.width;
  std::vector<double> power(static_cast<std::size_t>(n / 2 + 1), 0.0);
  for (int y = 0; y < img.height; ++y)
    for (int k = 0; k <= n / 2; ++k) {
      const cv::Vec2d v = spec.at<cv::Vec2d>(y, k);
      const bool paired = k > 0 && 2 * k != n;  // ±k both hold this frequency
      power[static_cast<std::size_t>(k)] += (v[0] * v[0] + v[1] * v[1]) / (double(n) * n) * (paired ? 2 : 1);
    }
  for (auto& p : power) p /= img.height;
  return power;
}

ZonePlateMeasures zoneplate_measures(const FloatImage& img, double numax, Band alias, Band pass) {
  if (!(numax > 0) || !std::isfinite(numax)) throw usage_error("zone plate: numax must be positive");
  if (!(alias.lo < alias.hi) || !(pass.lo < pass.hi)) throw usage_error("metrics: a band needs lo < hi");
  ZonePlateMeasures z;
  double alias_sum = 0, pass_sum = 0, ideal_sum = 0;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) {
      const double nu = zoneplate_frequency(numax, img.width, img.height, i, j);
      const double v = grey(img, static_cast<std::size_t>(j) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(i)) - 0.5;
      if (nu > alias.lo && nu < alias.hi) {
        alias_sum += v * v;
        ++z.n_alias;
      }
      if (nu >= pass.lo && nu < pass.hi) {
        const double ideal = zoneplate_value(numax, img.width, img.height, i + 0.5, j + 0.5) - 0.5;
        pass_sum += v * v;
        ideal_sum += ideal * ideal;
        ++z.n_pass;
      }
    }
  if (z.n_alias == 0 || z.n_pass == 0 || ideal_sum <= 0)
    throw bad_input("zone plate: the {}x{} image has no pixel in the alias or pass band", img.width, img.height);
  z.ae = alias_sum / static_cast<double>(z.n_alias) / 0.125;
  z.pr = pass_sum / ideal_sum;
  return z;
}

}  // namespace fest::sampling
