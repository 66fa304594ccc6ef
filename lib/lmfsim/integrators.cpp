#include "lmfsim/integrators.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fest::lmfsim {
namespace {

struct Workspace {
  Eigen::VectorXd k[7], tmp;
};

void rk4(System& sys, double t, double h, Eigen::VectorXd& s, Workspace& w, StepCounters& c) {
  sys.derivative(t, s, w.k[0]);
  w.tmp = s + 0.5 * h * w.k[0];
  sys.derivative(t + 0.5 * h, w.tmp, w.k[1]);
  w.tmp = s + 0.5 * h * w.k[1];
  sys.derivative(t + 0.5 * h, w.tmp, w.k[2]);
  w.tmp = s + h * w.k[2];
  sys.derivative(t + h, w.tmp, w.k[3]);
  s += (h / 6) * (w.k[0] + 2 * w.k[1] + 2 * w.k[2] + w.k[3]);
  c.evals += 4;
}

// Dormand-Prince 5(4) tableau.
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176, a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525,
                 e7 = -1.0 / 40;

// One attempted DP step; returns the scaled error norm, result in `out`.
double dopri_try(System& sys, double t, double h, const Eigen::VectorXd& s, Workspace& w, Eigen::VectorXd& out,
                 double rtol, double atol, StepCounters& c) {
  auto& k = w.k;
  sys.derivative(t, s, k[0]);
  sys.derivative(t + c2 * h, s + h * a21 * k[0], k[1]);
  sys.derivative(t + c3 * h, s + h * (a31 * k[0] + a32 * k[1]), k[2]);
  sys.derivative(t + c4 * h, s + h * (a41 * k[0] + a42 * k[1] + a43 * k[2]), k[3]);
  sys.derivative(t + c5 * h, s + h * (a51 * k[0] + a52 * k[1] + a53 * k[2] + a54 * k[3]), k[4]);
  sys.derivative(t + h, s + h * (a61 * k[0] + a62 * k[1] + a63 * k[2] + a64 * k[3] + a65 * k[4]), k[5]);
  out = s + h * (b1 * k[0] + b3 * k[2] + b4 * k[3] + b5 * k[4] + b6 * k[5]);
  sys.derivative(t + h, out, k[6]);
  c.evals += 7;
  const Eigen::VectorXd err = h * (e1 * k[0] + e3 * k[2] + e4 * k[3] + e5 * k[4] + e6 * k[5] + e7 * k[6]);
  double norm = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    const double sc = atol + rtol * std::max(std::abs(s[i]), std::abs(out[i]));
    norm = std::max(norm, std::abs(err[i]) / sc);
  }
  return norm;
}

}  // namespace

void advance(System& sys, Integrator method, double t, double h, Eigen::VectorXd& s, StepCounters& c, double& h_try) {
  static thread_local Workspace w;
  switch (method) {
    case Integrator::euler:
      sys.derivative(t, s, w.k[0]);
      s += h * w.k[0];
      c.evals += 1;
      break;
    case Integrator::symplectic: {
      // v <- v + h a(x, v); x <- x + h v (with the new v).
      sys.derivative(t, s, w.k[0]);
      const auto& mask = sys.velocity_mask();
      for (Eigen::Index i = 0; i < s.size(); ++i)
        if (mask[static_cast<std::size_t>(i)]) s[i] += h * w.k[0][i];
      sys.kinematic_rate(t, s, w.k[1]);
      for (Eigen::Index i = 0; i < s.size(); ++i)
        if (!mask[static_cast<std::size_t>(i)]) s[i] += h * w.k[1][i];
      c.evals += 1;
      break;
    }
    case Integrator::rk4: rk4(sys, t, h, s, w, c); break;
    case Integrator::rk45: {
      const double rtol = sys.settings().rtol, atol = sys.settings().atol;
      double tt = t;
      const double t_end = t + h;
      if (!(h_try > 0)) h_try = h;
      Eigen::VectorXd out;
      while (t_end - tt > 1e-14 * std::max(1.0, std::abs(t_end))) {
        const double hh = std::min(h_try, t_end - tt);
        const double err = dopri_try(sys, tt, hh, s, w, out, rtol, atol, c);
        const double factor = err == 0 ? 5.0 : std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0);
        if (err <= 1 && std::isfinite(err)) {
          tt += hh;
          s = out;
          sys.normalize(s);
          if (hh == h_try || factor < 1) h_try = hh * factor;
        } else {
          ++c.rejected;
          h_try = hh * std::min(factor, 0.5);
          if (!(h_try > 1e-14 * std::max(1.0, std::abs(tt))))
            throw runtime_failure("rk45 step size underflow (t={:.6g})", tt);
        }
      }
      c.steps += 1;
      return;
    }
  }
  sys.normalize(s);
  c.steps += 1;
}

}  // namespace fest::lmfsim
