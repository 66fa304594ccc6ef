#include "lmfsim/spline.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace fest::lmfsim {

Spline::Spline(std::vector<double> t, std::vector<double> y) : t_(std::move(t)), y_(std::move(y)) {
  const std::size_t n = t_.size();
  if (n == 0 || n != y_.size()) throw bad_input("spline needs at least one key");
  for (std::size_t i = 1; i < n; ++i)
    if (!(t_[i] > t_[i - 1])) throw bad_input("spline key times must increase ({} after {})", t_[i], t_[i - 1]);
  m_.assign(n, 0.0);
  if (n < 3) return;
  // Tridiagonal system for the interior second derivatives (natural ends: m = 0).
  std::vector<double> diag(n, 0.0), rhs(n, 0.0), upper(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t_[i] - t_[i - 1], h1 = t_[i + 1] - t_[i];
    diag[i] = 2 * (h0 + h1);
    upper[i] = h1;
    rhs[i] = 6 * ((y_[i + 1] - y_[i]) / h1 - (y_[i] - y_[i - 1]) / h0);
    if (i > 1) {  // eliminate the sub-diagonal entry h0
      const double f = h0 / diag[i - 1];
      diag[i] -= f * upper[i - 1];
      rhs[i] -= f * rhs[i - 1];
    }
  }
  for (std::size_t i = n - 2; i >= 1; --i) {
    m_[i] = (rhs[i] - upper[i] * m_[i + 1]) / diag[i];
    if (i == 1) break;
  }
}

std::size_t Spline::segment(double t) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  std::size_t i = static_cast<std::size_t>(it - t_.begin());
  return i == 0 ? 0 : std::min(i - 1, t_.size() - 2);
}

double Spline::value(double t) const {
  if (t_.size() == 1 || t <= t_.front()) return y_.front();
  if (t >= t_.back()) return y_.back();
  const std::size_t i = segment(t);
  const double h = t_[i + 1] - t_[i], a = (t_[i + 1] - t) / h, b = (t - t_[i]) / h;
  return a * y_[i] + b * y_[i + 1] + ((a * a * a - a) * m_[i] + (b * b * b - b) * m_[i + 1]) * h * h / 6;
}

double Spline::derivative(double t) const {
  if (t_.size() == 1 || t <= t_.front() || t >= t_.back()) return 0;
  const std::size_t i = segment(t);
  const double h = t_[i + 1] - t_[i], a = (t_[i + 1] - t) / h, b = (t - t_[i]) / h;
  return (y_[i + 1] - y_[i]) / h + ((1 - 3 * a * a) * m_[i] + (3 * b * b - 1) * m_[i + 1]) * h / 6;
}

double Spline::second_derivative(double t) const {
  if (t_.size() == 1 || t <= t_.front() || t >= t_.back()) return 0;
  const std::size_t i = segment(t);
  const double h = t_[i + 1] - t_[i], a = (t_[i + 1] - t) / h, b = (t - t_[i]) / h;
  return a * m_[i] + b * m_[i + 1];
}

}  // namespace fest::lmfsim
