// Gaussian smoothing, percentiles, Otsu, thresholds.
#include "segbrain/filters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fest::segbrain {

Image gaussian_smooth(const Grid& g, const Image& img, double sigma_mm) {
  Image cur = img;
  if (sigma_mm <= 0) return cur;
  // Lines along y and z are gathered kBlock at a time from consecutive x so the strided
  // reads use whole cache lines; the line is padded by replicating its ends, so the
  // convolution itself needs no bounds checks.
  constexpr std::size_t kBlock = 16;
  for (int axis = 0; axis < 3; ++axis) {
    const double s = sigma_mm / g.spacing[axis];
    const int r = static_cast<int>(std::ceil(3 * s));
    std::vector<double> w(2 * r + 1);
    double sum = 0;
    for (int i = -r; i <= r; ++i) sum += w[i + r] = std::exp(-0.5 * i * i / (s * s));
    for (auto& x : w) x /= sum;
    const std::size_t n = g.n[axis];
    const std::size_t stride = axis == 0 ? 1 : axis == 1 ? g.n[0] : g.n[0] * g.n[1];
    std::vector<std::vector<double>> line(kBlock, std::vector<double>(n + 2 * r));
    std::vector<std::vector<float>> res(kBlock, std::vector<float>(n));
    const std::size_t xstep = axis == 0 ? 1 : kBlock;
    for (std::size_t z = 0; z < (axis == 2 ? 1 : g.n[2]); ++z)
      for (std::size_t y = 0; y < (axis == 1 ? 1 : g.n[1]); ++y)
        for (std::size_t x0 = 0; x0 < (axis == 0 ? 1 : g.n[0]); x0 += xstep) {
          const std::size_t nb = axis == 0 ? 1 : std::min(kBlock, g.n[0] - x0);
          const std::size_t base = g.index(x0, y, z);
          for (std::size_t i = 0; i < n; ++i)
            for (std::size_t b = 0; b < nb; ++b) line[b][i + r] = cur[base + b + i * stride];
          for (std::size_t b = 0; b < nb; ++b) {
            auto& l = line[b];
            for (int k = 0; k < r; ++k) {
              l[k] = l[r];
              l[n + r + k] = l[n + r - 1];
            }
            for (std::size_t i = 0; i < n; ++i) {
              double acc = 0;
              const double* p = &l[i];
              for (int k = 0; k <= 2 * r; ++k) acc += w[k] * p[k];
              res[b][i] = static_cast<float>(acc);
            }
          }
          for (std::size_t i = 0; i < n; ++i)
            for (std::size_t b = 0; b < nb; ++b) cur[base + b + i * stride] = res[b][i];
        }
  }
  return cur;
}

double percentile(const Image& img, const Mask& mask, double p) {
  std::vector<float> v;
  v.reserve(img.size());
  for (std::size_t i = 0; i < img.size(); ++i)
    if ((mask.empty() || mask[i]) && std::isfinite(img[i])) v.push_back(img[i]);
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::size_t k = static_cast<std::size_t>(std::clamp(p / 100.0, 0.0, 1.0) * static_cast<double>(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

double otsu_threshold(const Image& img, const Mask& mask) {
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i < img.size(); ++i)
    if ((mask.empty() || mask[i]) && std::isfinite(img[i])) {
      lo = std::min(lo, double(img[i]));
      hi = std::max(hi, double(img[i]));
    }
  if (!(hi > lo)) return lo;
  constexpr int kBins = 256;
  std::vector<double> h(kBins, 0);
  const double width = (hi - lo) / kBins;
  for (std::size_t i = 0; i < img.size(); ++i)
    if ((mask.empty() || mask[i]) && std::isfinite(img[i]))
      h[std::min(kBins - 1, static_cast<int>((img[i] - lo) / width))] += 1;
  double total = 0, sum_all = 0;
  for (int b = 0; b < kBins; ++b) {
    total += h[b];
    sum_all += h[b] * (lo + (b + 0.5) * width);
  }
  std::vector<double> between(kBins - 1, -1);
  double w0 = 0, s0 = 0, best = -1;
  for (int b = 0; b < kBins - 1; ++b) {
    w0 += h[b];
    s0 += h[b] * (lo + (b + 0.5) * width);
    double w1 = total - w0;
    if (w0 == 0 || w1 == 0) continue;
    double m0 = s0 / w0, m1 = (sum_all - s0) / w1;
    between[b] = w0 * w1 * (m0 - m1) * (m0 - m1);
    best = std::max(best, between[b]);
  }
  // Empty bins between the classes give a plateau of equal values; its middle is the
  // threshold farthest from both classes.
  int first = -1, last = -1;
  for (int b = 0; b < kBins - 1; ++b)
    if (between[b] >= best * (1 - 1e-12)) {
      if (first < 0) first = b;
      last = b;
    }
  return lo + (0.5 * (first + last) + 1) * width;
}

Mask threshold(const Image& img, double lo, double hi) {
  Mask m(img.size());
  for (std::size_t i = 0; i < img.size(); ++i) m[i] = img[i] >= lo && img[i] <= hi;
  return m;
}

double fraction_within(const Image& img, const Mask& mask, double lo, double hi) {
  std::size_t n = 0, in = 0;
  for (std::size_t i = 0; i < img.size(); ++i)
    if (mask[i]) {
      ++n;
      in += img[i] >= lo && img[i] <= hi;
    }
  return n ? double(in) / double(n) : 0.0;
}

}  // namespace fest::segbrain
