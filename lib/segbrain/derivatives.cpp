// Gaussian derivative kernels and one-axis convolution.
#include "segbrain/derivatives.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fest::segbrain {

std::vector<double> gaussian_derivative_kernel(double sigma_vox, int order) {
  if (!(sigma_vox > 0)) throw bad_input("Gaussian sigma must be positive, got {}", sigma_vox);
  const int r = std::max(1, static_cast<int>(std::ceil(3 * sigma_vox)));
  std::vector<double> k(2 * r + 1);
  const double s2 = sigma_vox * sigma_vox;
  for (int i = -r; i <= r; ++i) {
    const double g = std::exp(-0.5 * i * i / s2);
    k[i + r] = order == 0 ? g : order == 1 ? -i / s2 * g : (i * i / s2 - 1) / s2 * g;
  }
  // Truncation and sampling spoil the moments a little; restore the ones that matter.
  if (order == 0) {
    double sum = 0;
    for (double v : k) sum += v;
    for (double& v : k) v /= sum;
  } else if (order == 1) {
    double m1 = 0;
    for (int i = -r; i <= r; ++i) m1 += i * k[i + r];
    for (double& v : k) v /= -m1;  // sum(i * k) = -1: convolution of the ramp i gives 1
  } else {
    // Zero sum by removing a multiple of the Gaussian itself (a constant would turn the
    // positive tails negative and add zero crossings far from an edge).
    double sum = 0, gsum = 0;
    for (double v : k) sum += v;
    for (int i = -r; i <= r; ++i) gsum += std::exp(-0.5 * i * i / s2);
    for (int i = -r; i <= r; ++i) k[i + r] -= sum / gsum * std::exp(-0.5 * i * i / s2);
    double m2 = 0;
    for (int i = -r; i <= r; ++i) m2 += double(i) * i * k[i + r];
    for (double& v : k) v *= 2 / m2;  // sum(i^2 k) = 2: convolution of i^2 gives 2
  }
  return k;
}

Image convolve_axis(const Grid& g, const Image& img, int axis, const std::vector<double>& kernel, int scale_power) {
  const long r = static_cast<long>(kernel.size() / 2);
  const double scale = 1.0 / std::pow(g.spacing[axis], scale_power);
  Image out(img.size());
  if (axis == 0) {
    const std::size_t n = g.n[0];
    std::vector<double> line(n + 2 * std::size_t(r));
    for (std::size_t base = 0; base < img.size(); base += n) {
      for (std::size_t i = 0; i < n; ++i) line[i + std::size_t(r)] = img[base + i];
      for (long k = 0; k < r; ++k) {
        line[std::size_t(k)] = line[std::size_t(r)];
        line[n + std::size_t(r + k)] = line[n + std::size_t(r) - 1];
      }
      // Correlation with the mirrored kernel is the convolution.
      for (std::size_t i = 0; i < n; ++i) {
        double acc = 0;
        for (long k = -r; k <= r; ++k) acc += kernel[std::size_t(r - k)] * line[i + std::size_t(r + k)];
        out[base + i] = static_cast<float>(acc * scale);
      }
    }
    return out;
  }
  // Along A or S whole rows (A) or planes (S) are combined at once: the reads stay
  // contiguous instead of striding through the volume.
  const std::size_t n = g.n[axis];
  const std::size_t row = axis == 1 ? g.n[0] : g.n[0] * g.n[1];   // contiguous run
  const std::size_t outer = axis == 1 ? g.n[2] : 1;                // independent blocks
  const std::size_t block = row * n;
  std::vector<double> acc(row);
  for (std::size_t o = 0; o < outer; ++o) {
    const float* src = img.data() + o * block;
    float* dst = out.data() + o * block;
    for (long i = 0; i < long(n); ++i) {
      std::fill(acc.begin(), acc.end(), 0.0);
      for (long k = -r; k <= r; ++k) {
        const long j = std::clamp(i - k, 0L, long(n) - 1);  // replicated border
        const double w = kernel[std::size_t(k + r)];
        const float* s = src + std::size_t(j) * row;
        for (std::size_t x = 0; x < row; ++x) acc[x] += w * s[x];
      }
      float* d = dst + std::size_t(i) * row;
      for (std::size_t x = 0; x < row; ++x) d[x] = static_cast<float>(acc[x] * scale);
    }
  }
  return out;
}

Image gaussian_derivative(const Grid& g, const Image& img, double sigma_mm, const int orders[3], const bool skip[3]) {
  Image cur = img;
  for (int a = 0; a < 3; ++a) {
    if (skip[a]) continue;
    cur = convolve_axis(g, cur, a, gaussian_derivative_kernel(sigma_mm / g.spacing[a], orders[a]), orders[a]);
  }
  return cur;
}

}  // namespace fest::segbrain
