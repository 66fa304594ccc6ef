// 1-D k-means and nearest-mean classification.
#include "segbrain/classify.hpp"

#include <algorithm>
#include <cmath>

#include "segbrain/filters.hpp"

namespace fest::segbrain {

std::vector<double> kmeans_1d(const Image& img, const Mask& mask, int k, int iterations) {
  std::vector<float> v;
  for (std::size_t i = 0; i < img.size(); ++i)
    if (mask[i] && std::isfinite(img[i])) v.push_back(img[i]);
  if (v.empty() || k < 1) return {};
  std::sort(v.begin(), v.end());
  std::vector<double> means(static_cast<std::size_t>(k));
  for (int c = 0; c < k; ++c) {
    const double p = k == 1 ? 0.5 : 0.1 + 0.8 * c / (k - 1);
    means[std::size_t(c)] = v[std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size())))];
  }
  // On sorted values each class is a contiguous run between midpoints of the means.
  for (int it = 0; it < iterations; ++it) {
    std::vector<double> next = means;
    std::size_t from = 0;
    for (int c = 0; c < k; ++c) {
      const double upper = c + 1 < k ? 0.5 * (means[std::size_t(c)] + means[std::size_t(c) + 1]) : INFINITY;
      const std::size_t to = std::size_t(std::upper_bound(v.begin() + long(from), v.end(), upper) - v.begin());
      double s = 0;
      for (std::size_t i = from; i < to; ++i) s += v[i];
      if (to > from) next[std::size_t(c)] = s / double(to - from);
      from = to;
    }
    std::sort(next.begin(), next.end());
    if (next == means) break;
    means = next;
  }
  return means;
}

Mask nearest_class(const Image& img, const Mask& mask, const std::vector<double>& means, std::size_t index) {
  Mask out(img.size(), 0);
  for (std::size_t i = 0; i < img.size(); ++i) {
    if (!mask[i]) continue;
    std::size_t best = 0;
    for (std::size_t c = 1; c < means.size(); ++c)
      if (std::abs(img[i] - means[c]) < std::abs(img[i] - means[best])) best = c;
    out[i] = best == index;
  }
  return out;
}

}  // namespace fest::segbrain
