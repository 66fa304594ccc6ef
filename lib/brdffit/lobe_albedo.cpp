#include "brdffit/lobe_albedo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace fest::brdffit {

namespace {

constexpr int kNodes = 64;        // quadrature nodes in t (see lobe_integral)
constexpr int kAngles = 33;       // grid of incident polar angles
constexpr int kGoldenSteps = 30;  // refinement of the best grid angle

// Integral over phi in [0, 2 pi) of max(0, a + b cos phi), b >= 0.
double clipped_cosine_ring(double a, double b) {
  if (a >= b) return 2 * M_PI * a;
  if (a <= -b) return 0;
  const double phi0 = std::acos(-a / b);
  return 2 * (a * phi0 + b * std::sin(phi0));
}

// The lobe's shape integral for a unit lobe axis w with height z = w_z:
//   I(z) = integral over {v : v.w > 0} of (v.w)^N max(0, v_z) dw_v.
// In polar coordinates (alpha, phi) about w, v_z = cos(alpha) z + sin(alpha) cos(phi)
// sqrt(1 - z^2); the substitution t = cos(alpha)^(N + 1) absorbs cos^N(alpha) sin(alpha)
// dalpha = -dt / (N + 1), so the nodes follow the lobe however sharp it is.
struct LobeNodes {
  std::array<double, kNodes> cos_a{}, sin_a{};
  explicit LobeNodes(double n) {
    for (int i = 0; i < kNodes; ++i) {
      const double t = (i + 0.5) / kNodes;  // midpoint rule
      cos_a[i] = std::pow(t, 1 / (n + 1));
      sin_a[i] = std::sqrt(std::max(0.0, 1 - cos_a[i] * cos_a[i]));
    }
  }
  double integral(double z, double n) const {
    const double s = std::sqrt(std::max(0.0, 1 - z * z));
    double sum = 0;
    for (int i = 0; i < kNodes; ++i) sum += clipped_cosine_ring(cos_a[i] * z, sin_a[i] * s);
    return sum / kNodes / (n + 1);
  }
};

}  // namespace

double lobe_log_max_albedo(double cxy, double cz, double n) {
  const LobeNodes nodes(n);
  // Isotropy: only the incident polar angle theta matters; for u = (sin, 0, cos) the lobe
  // is (w.v)^N with w = (Cxy sin theta, 0, Cz cos theta).
  auto log_albedo = [&](double theta) {
    const double wx = cxy * std::sin(theta), wz = cz * std::cos(theta);
    const double m = std::hypot(wx, wz);
    if (!(m > 0)) return -std::numeric_limits<double>::infinity();
    const double shape = nodes.integral(wz / m, n);
    if (!(shape > 0)) return -std::numeric_limits<double>::infinity();
    return n * std::log(m) + std::log(shape);
  };
  const double step = M_PI / 2 / (kAngles - 1);
  int best = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < kAngles; ++i) {
    const double v = log_albedo(i * step);
    if (v > best_value) best_value = v, best = i;
  }
  if (!std::isfinite(best_value)) return best_value;
  // Golden-section search in the grid cells either side of the best angle.
  double lo = std::max(0, best - 1) * step, hi = std::min(kAngles - 1, best + 1) * step;
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = log_albedo(x1), f2 = log_albedo(x2);
  for (int k = 0; k < kGoldenSteps; ++k) {
    if (f1 > f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo), f1 = log_albedo(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo), f2 = log_albedo(x2);
    }
  }
  return std::max({best_value, f1, f2});
}

}  // namespace fest::brdffit
