#include "sampling/kernel_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "sampling/frequency_response.hpp"

namespace fest::sampling {

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double step = 1e-4;  // docs/resample.md "Kernels and their responses"

bool has_finite_spatial(const Kernel& k) {
  return k.spatial && std::isfinite(k.radius) && k.radius > 0 && !k.nearest;
}

// The kernel sampled once on Simpson nodes: every probe frequency reuses the samples, so
// the scan costs one cosine per node and frequency instead of a kernel evaluation.
struct Samples {
  std::vector<double> x, weighted;  // nodes and Simpson weight × k(x)
  double area = 0;
  double h = 0;
};

Samples sample(const Kernel& k) {
  long n = static_cast<long>(std::ceil(2 * k.radius / step));
  if (n % 2) ++n;
  Samples s;
  s.h = 2 * k.radius / static_cast<double>(n);
  s.x.resize(static_cast<std::size_t>(n) + 1);
  s.weighted.resize(s.x.size());
  for (long i = 0; i <= n; ++i) {
    const double x = -k.radius + static_cast<double>(i) * s.h;
    const double simpson = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    s.x[static_cast<std::size_t>(i)] = x;
    s.weighted[static_cast<std::size_t>(i)] = simpson * k.spatial(x);
    s.area += s.weighted[static_cast<std::size_t>(i)];
  }
  return s;
}

double response(const Samples& s, double f) {
  double t = 0;
  const double w = 2 * pi * f;
  for (std::size_t i = 0; i < s.x.size(); ++i) t += s.weighted[i] * std::cos(w * s.x[i]);
  return t / s.area;
}

}  // namespace

KernelAnalysis analyse_kernel(const Kernel& k) {
  KernelAnalysis a;
  if (k.nearest) return a;  // point sampling has no prefilter to analyse
  if (!has_finite_spatial(k)) {
    a.k_quarter = frequency_response(k, 0.25);
    a.k_half = frequency_response(k, 0.5);
    for (double f = 0.75; f <= 3.0 + 1e-9; f += 0.005) a.stop_max = std::max(a.stop_max, std::fabs(frequency_response(k, f)));
    return a;
  }
  a.has_spatial = true;
  const Samples s = sample(k);
  a.k_quarter = response(s, 0.25);
  a.k_half = response(s, 0.5);
  for (int i = 0; i <= 450; ++i) a.stop_max = std::max(a.stop_max, std::fabs(response(s, 0.75 + 0.005 * i)));
  // Step response S(x) = ∫_{-r}^{x} k / ∫k by the trapezoid rule on the same nodes.
  double total = 0;
  for (std::size_t i = 1; i < s.x.size(); ++i) total += 0.5 * s.h * (k.spatial(s.x[i - 1]) + k.spatial(s.x[i]));
  double run = 0, lo = 0, hi = 0;
  for (std::size_t i = 1; i < s.x.size(); ++i) {
    run += 0.5 * s.h * (k.spatial(s.x[i - 1]) + k.spatial(s.x[i]));
    lo = std::min(lo, run / total);
    hi = std::max(hi, run / total);
  }
  a.overshoot = std::max(0.0, hi - 1);
  a.undershoot = std::max(0.0, -lo);
  return a;
}

Curve kernel_curve(const Kernel& k, int count) {
  if (!has_finite_spatial(k)) throw usage_error("kernel '{}' has no finite spatial form to tabulate", k.name);
  if (count < 2) throw usage_error("kernel curve: need at least 2 points");
  const Samples s = sample(k);
  const double area = s.area * s.h / 3;  // Simpson's ∫k
  Curve c;
  for (int i = 0; i < count; ++i) {
    const double x = -k.radius + 2 * k.radius * i / (count - 1);
    c.x.push_back(x);
    c.y.push_back(k.spatial(x) / area);
  }
  return c;
}

Curve response_curve(const Kernel& k, double f_max, int count) {
  if (count < 2 || !(f_max > 0)) throw usage_error("response curve: need f_max > 0 and at least 2 points");
  Curve c;
  if (k.nearest) throw usage_error("kernel 'point' has no frequency response (no prefilter)");
  const bool spatial = has_finite_spatial(k);
  Samples s;
  if (spatial) s = sample(k);
  for (int i = 0; i < count; ++i) {
    const double f = f_max * i / (count - 1);
    c.x.push_back(f);
    c.y.push_back(spatial ? response(s, f) : frequency_response(k, f));
  }
  return c;
}

}  // namespace fest::sampling
