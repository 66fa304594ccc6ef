// Gaussian smoothing, percentiles, Otsu, thresholds.
#include "segbrain/filters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "segbrain/parallel.hpp"

namespace fest::segbrain {

namespace {

// Normalised samples of the Gaussian of standard deviation s voxels, radius ceil(3 s).
std::vector<double> gaussian_weights(double s) {
  const int r = static_cast<int>(std::ceil(3 * s));
  std::vector<double> w(2 * static_cast<std::size_t>(r) + 1);
  double sum = 0;
  for (int i = -r; i <= r; ++i) sum += w[static_cast<std::size_t>(i + r)] = std::exp(-0.5 * i * i / (s * s));
  for (auto& x : w) x /= sum;
  return w;
}

// Convolves `lanes` interleaved lines of n samples: in holds sample i of lane b at
// in[(i + r) * lanes + b], with the r samples beyond each end already replicated; out
// receives n * lanes sums. Eight outputs at a time keep their sums in registers while the
// taps run (the eight lanes vectorise), and every output sums its taps in the order
// k = 0..2r, the order of the plain convolution.
void convolve_lanes(const double* in, std::size_t n, std::size_t lanes, const std::vector<double>& w, double* out) {
  const std::size_t m = n * lanes, taps = w.size();
  std::size_t j = 0;
  for (; j + 8 <= m; j += 8) {
    double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (std::size_t k = 0; k < taps; ++k) {
      const double wk = w[k];
      const double* src = in + j + k * lanes;
      for (int t = 0; t < 8; ++t) acc[t] += wk * src[t];
    }
    for (int t = 0; t < 8; ++t) out[j + static_cast<std::size_t>(t)] = acc[t];
  }
  for (; j < m; ++j) {
    double acc = 0;
    for (std::size_t k = 0; k < taps; ++k) acc += w[k] * in[j + k * lanes];
    out[j] = acc;
  }
}

// One pass along `axis` over lines that start at base + x * 1 (x < lanes) and step
// `stride`: gathers the lanes with replicated ends, convolves, writes back as float.
struct Pass {
  std::vector<double> in, out;
  void run(float* base, std::size_t lanes, std::size_t n, std::size_t stride, const std::vector<double>& w) {
    const std::size_t r = w.size() / 2;
    in.resize((n + 2 * r) * lanes);
    out.resize(n * lanes);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t b = 0; b < lanes; ++b) in[(i + r) * lanes + b] = base[b + i * stride];
    for (std::size_t k = 0; k < r; ++k)
      for (std::size_t b = 0; b < lanes; ++b) {
        in[k * lanes + b] = in[r * lanes + b];
        in[(n + r + k) * lanes + b] = in[(n + r - 1) * lanes + b];
      }
    convolve_lanes(in.data(), n, lanes, w, out.data());
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t b = 0; b < lanes; ++b) base[b + i * stride] = static_cast<float>(out[i * lanes + b]);
  }
};

}  // namespace

Image gaussian_smooth(const Grid& g, const Image& img, double sigma_mm) {
  Image cur = img;
  if (sigma_mm <= 0 || g.size() == 0) return cur;
  std::array<std::vector<double>, 3> w;
  for (int a = 0; a < 3; ++a) w[a] = gaussian_weights(sigma_mm / g.spacing[a]);
  const std::size_t nx = g.n[0], ny = g.n[1], nz = g.n[2];
  // Lines along y and z are taken kBlock at a time from consecutive x, so the strided
  // reads use whole cache lines. x and y stay within an axial slice: one band of slices
  // per thread; then z, one band of coronal planes per thread.
  constexpr std::size_t kBlock = 16;
  parallel_bands(nz, 4, [&](std::size_t, std::size_t z0, std::size_t z1) {
    Pass p;
    for (std::size_t z = z0; z < z1; ++z) {
      for (std::size_t y = 0; y < ny; ++y) p.run(cur.data() + g.index(0, y, z), 1, nx, 1, w[0]);
      for (std::size_t x0 = 0; x0 < nx; x0 += kBlock)
        p.run(cur.data() + g.index(x0, 0, z), std::min(kBlock, nx - x0), ny, nx, w[1]);
    }
  });
  parallel_bands(ny, 4, [&](std::size_t, std::size_t y0, std::size_t y1) {
    Pass p;
    for (std::size_t y = y0; y < y1; ++y)
      for (std::size_t x0 = 0; x0 < nx; x0 += kBlock)
        p.run(cur.data() + g.index(x0, y, 0), std::min(kBlock, nx - x0), nz, nx * ny, w[2]);
  });
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

namespace {

// The float bounds equivalent to double ones for float voxels x: x >= lo exactly when
// x >= lower_bound_float(lo), x <= hi exactly when x <= upper_bound_float(hi) (NaN stays
// NaN), so the comparisons can run on floats, four or eight to an instruction.
float lower_bound_float(double lo) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (std::isnan(lo) || lo == -INFINITY) return static_cast<float>(lo);
  if (lo > kMax) return INFINITY;
  if (lo < -kMax) return -std::numeric_limits<float>::max();
  float f = static_cast<float>(lo);
  if (static_cast<double>(f) < lo) f = std::nextafter(f, INFINITY);
  return f;
}
float upper_bound_float(double hi) { return -lower_bound_float(-hi); }

}  // namespace

Mask threshold(const Image& img, double lo, double hi) {
  Mask m(img.size());
  const float flo = lower_bound_float(lo), fhi = upper_bound_float(hi);
  const float* x = img.data();
  std::uint8_t* out = m.data();
  const std::size_t n = img.size();  // hoisted: a uint8_t store may alias the vector's own size
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>((x[i] >= flo) & (x[i] <= fhi));
  return m;
}

Mask combine(const Mask& a, const Mask& b, MaskLogic op) {
  Mask m(a.size());
  const std::uint8_t* x = a.data();
  const std::uint8_t* y = b.data();
  std::uint8_t* out = m.data();
  const std::size_t n = std::min(a.size(), b.size());
  // One branch-free loop per operation, so each vectorises.
  switch (op) {
    case MaskLogic::both:
      for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>((x[i] != 0) & (y[i] != 0));
      break;
    case MaskLogic::either:
      for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>((x[i] != 0) | (y[i] != 0));
      break;
    case MaskLogic::first_only:
      for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>((x[i] != 0) & (y[i] == 0));
      break;
  }
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
