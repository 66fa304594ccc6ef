#include "sampling/line_filters.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include <opencv2/core.hpp>

#include "core/error.hpp"
#include "core/threads.hpp"

namespace fest::sampling {

namespace {

constexpr double pi = 3.14159265358979323846;

// The lines of an image along an axis: count, length, and the stride between elements.
struct Lines {
  int count, length;
  std::size_t start_step, element_step;
};

Lines lines_of(const FloatImage& img, Axis axis) {
  const auto c = static_cast<std::size_t>(img.channels);
  const auto row = static_cast<std::size_t>(img.width) * c;
  if (axis == Axis::x) return {img.height * img.channels, img.width, 0, c};
  return {img.width * img.channels, img.height, 0, row};
}

std::size_t line_start(const FloatImage& img, Axis axis, int line) {
  const auto c = static_cast<std::size_t>(img.channels);
  const auto l = static_cast<std::size_t>(line);
  if (axis == Axis::x) return (l / c) * static_cast<std::size_t>(img.width) * c + l % c;
  return l;  // column-major lines start in row 0: channel-interleaved column index
}

// Runs body(line) over the lines, split among threads (each line independent).
template <typename Body>
void for_lines(int count, int threads, Body body) {
  const int n = std::max(1, std::min(threads, count));
  std::vector<std::thread> pool;
  auto block = [&](int t) {
    const int begin = static_cast<int>(static_cast<long long>(count) * t / n);
    const int end = static_cast<int>(static_cast<long long>(count) * (t + 1) / n);
    for (int i = begin; i < end; ++i) body(i);
  };
  if (n == 1) return block(0);
  for (int t = 0; t < n; ++t) pool.emplace_back(block, t);
  for (auto& th : pool) th.join();
}

void filter_pole(std::vector<double>& c, double z) {
  const std::size_t n = c.size();
  // Causal init: Σ z^k c[k] over the horizon where z^k is negligible (mirror boundary).
  const std::size_t horizon = std::min(n, static_cast<std::size_t>(std::ceil(std::log(1e-12) / std::log(std::fabs(z)))) + 1);
  double sum = 0, zk = 1;
  for (std::size_t k = 0; k < horizon; ++k, zk *= z) sum += zk * c[k];
  c[0] = sum;
  for (std::size_t k = 1; k < n; ++k) c[k] += z * c[k - 1];
  // Anticausal init for the mirror extension.
  c[n - 1] = (z / (z * z - 1)) * (c[n - 1] + z * c[n - 2]);
  for (std::size_t k = n - 1; k-- > 0;) c[k] = z * (c[k + 1] - c[k]);
}

// DCT-II of a line through a complex DFT of its mirror extension (length 2N):
// C_k = Σ_n x_n cos(πk(n + ½)/N) = ½ Re(Y_k e^{−iπk/2N}).
std::vector<double> dct2(const std::vector<double>& x) {
  const int n = static_cast<int>(x.size());
  cv::Mat y(1, 2 * n, CV_64FC2, cv::Scalar(0, 0));
  for (int i = 0; i < n; ++i) {
    y.at<cv::Vec2d>(0, i)[0] = x[static_cast<std::size_t>(i)];
    y.at<cv::Vec2d>(0, 2 * n - 1 - i)[0] = x[static_cast<std::size_t>(i)];
  }
  cv::Mat spec;
  cv::dft(y, spec, cv::DFT_COMPLEX_OUTPUT);
  std::vector<double> c(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const cv::Vec2d v = spec.at<cv::Vec2d>(0, k);
    const double a = -pi * k / (2.0 * n);
    c[static_cast<std::size_t>(k)] = 0.5 * (v[0] * std::cos(a) - v[1] * std::sin(a));
  }
  return c;
}

// The continuous cosine series of a line of length N (DCT-II coefficients C), read at the
// centres of M pixels over the same extent, keeping the first `keep` terms:
// y_m = (1/N)[C_0 + 2 Σ_{k≥1} C_k cos(πk(m + ½)/M)], via an inverse DFT of length 2M.
std::vector<double> read_series(const std::vector<double>& c, int n, int m, int keep) {
  cv::Mat z(1, 2 * m, CV_64FC2, cv::Scalar(0, 0));
  for (int k = 0; k < keep; ++k) {
    const double w = (k == 0 ? 1.0 : 2.0) * c[static_cast<std::size_t>(k)] / n;
    const double a = pi * k / (2.0 * m);
    z.at<cv::Vec2d>(0, k) = cv::Vec2d(w * std::cos(a), w * std::sin(a));
  }
  cv::Mat out;
  cv::dft(z, out, cv::DFT_INVERSE | cv::DFT_COMPLEX_OUTPUT);  // unscaled: Σ_k Z_k e^{+2πikm/2M}
  std::vector<double> y(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) y[static_cast<std::size_t>(i)] = out.at<cv::Vec2d>(0, i)[0];
  return y;
}

}  // namespace

void recursive_inverse(FloatImage& img, Axis axis, const std::vector<double>& poles, int threads) {
  const Lines ls = lines_of(img, axis);
  if (ls.length < 2) return;  // a single sample: the filter's DC gain is 1
  double gain = 1;
  for (double z : poles) gain *= (1 - z) * (1 - 1 / z);
  for_lines(ls.count, resolve_threads(threads), [&](int line) {
    float* base = img.data.data() + line_start(img, axis, line);
    std::vector<double> c(static_cast<std::size_t>(ls.length));
    for (int i = 0; i < ls.length; ++i) c[static_cast<std::size_t>(i)] = gain * base[static_cast<std::size_t>(i) * ls.element_step];
    for (double z : poles) filter_pole(c, z);
    for (int i = 0; i < ls.length; ++i) base[static_cast<std::size_t>(i) * ls.element_step] = static_cast<float>(c[static_cast<std::size_t>(i)]);
  });
}

void spectral_filter(FloatImage& img, Axis axis, const std::function<double(double)>& gain, int threads) {
  const Lines ls = lines_of(img, axis);
  std::vector<double> g(static_cast<std::size_t>(ls.length));
  for (int k = 0; k < ls.length; ++k) g[static_cast<std::size_t>(k)] = gain(k / (2.0 * ls.length));
  for_lines(ls.count, resolve_threads(threads), [&](int line) {
    float* base = img.data.data() + line_start(img, axis, line);
    std::vector<double> x(static_cast<std::size_t>(ls.length));
    for (int i = 0; i < ls.length; ++i) x[static_cast<std::size_t>(i)] = base[static_cast<std::size_t>(i) * ls.element_step];
    std::vector<double> c = dct2(x);
    for (int k = 0; k < ls.length; ++k) c[static_cast<std::size_t>(k)] *= g[static_cast<std::size_t>(k)];
    const std::vector<double> y = read_series(c, ls.length, ls.length, ls.length);
    for (int i = 0; i < ls.length; ++i) base[static_cast<std::size_t>(i) * ls.element_step] = static_cast<float>(y[static_cast<std::size_t>(i)]);
  });
}

FloatImage spectral_resample(const FloatImage& img, Axis axis, int n_out, int threads) {
  if (n_out <= 0) throw usage_error("spectral resample: size {} must be positive", n_out);
  FloatImage out = axis == Axis::x ? FloatImage(n_out, img.height, img.channels) : FloatImage(img.width, n_out, img.channels);
  const Lines in_lines = lines_of(img, axis), out_lines = lines_of(out, axis);
  const int keep = std::min(in_lines.length, n_out);
  for_lines(in_lines.count, resolve_threads(threads), [&](int line) {
    const float* src = img.data.data() + line_start(img, axis, line);
    float* dst = out.data.data() + line_start(out, axis, line);
    std::vector<double> x(static_cast<std::size_t>(in_lines.length));
    for (int i = 0; i < in_lines.length; ++i) x[static_cast<std::size_t>(i)] = src[static_cast<std::size_t>(i) * in_lines.element_step];
    const std::vector<double> y = read_series(dct2(x), in_lines.length, n_out, keep);
    for (int i = 0; i < n_out; ++i) dst[static_cast<std::size_t>(i) * out_lines.element_step] = static_cast<float>(y[static_cast<std::size_t>(i)]);
  });
  return out;
}

}  // namespace fest::sampling
