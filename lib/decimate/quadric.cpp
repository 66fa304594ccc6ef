#include "decimate/quadric.hpp"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace fest::decimate {

namespace {
double dot(const double* x, const double* y, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += x[i] * y[i];
  return s;
}
}  // namespace

Quadric Quadric::triangle(const double* p, const double* q, const double* r, int n, double weight) {
  Quadric out(n);
  double e1[max_dimension], e2[max_dimension];
  for (int i = 0; i < n; ++i) {
    e1[i] = q[i] - p[i];
    e2[i] = r[i] - p[i];
  }
  const double l1 = std::sqrt(dot(e1, e1, n));
  if (!(l1 > 0)) return out;
  for (int i = 0; i < n; ++i) e1[i] /= l1;
  const double d = dot(e1, e2, n);
  for (int i = 0; i < n; ++i) e2[i] -= d * e1[i];
  const double l2 = std::sqrt(dot(e2, e2, n));
  if (!(l2 > 0)) return out;
  for (int i = 0; i < n; ++i) e2[i] /= l2;
  const double pe1 = dot(p, e1, n), pe2 = dot(p, e2, n);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j)
      out.a_[out.index(i, j)] = weight * ((i == j ? 1.0 : 0.0) - e1[i] * e1[j] - e2[i] * e2[j]);
  for (int i = 0; i < n; ++i) out.b_[static_cast<std::size_t>(i)] = weight * (pe1 * e1[i] + pe2 * e2[i] - p[i]);
  out.c_ = weight * (dot(p, p, n) - pe1 * pe1 - pe2 * pe2);
  out.w_ = weight;
  return out;
}

Quadric Quadric::position_plane(const double point[3], const double normal[3], int n, double weight) {
  Quadric out(n);
  const double d = -(normal[0] * point[0] + normal[1] * point[1] + normal[2] * point[2]);
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) out.a_[out.index(i, j)] = weight * normal[i] * normal[j];
    out.b_[static_cast<std::size_t>(i)] = weight * d * normal[i];
  }
  out.c_ = weight * d * d;
  out.w_ = 0;  // constraint planes add no surface area
  return out;
}

Quadric& Quadric::operator+=(const Quadric& o) {
  const std::size_t na = static_cast<std::size_t>(n_ * (n_ + 1) / 2);
  for (std::size_t i = 0; i < na; ++i) a_[i] += o.a_[i];
  for (std::size_t i = 0; i < static_cast<std::size_t>(n_); ++i) b_[i] += o.b_[i];
  c_ += o.c_;
  w_ += o.w_;
  return *this;
}

Quadric Quadric::unpack(const double* packed, int n) {
  Quadric q(n);
  const std::size_t na = static_cast<std::size_t>(n * (n + 1) / 2);
  for (std::size_t i = 0; i < na; ++i) q.a_[i] = packed[i];
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) q.b_[i] = packed[na + i];
  q.c_ = packed[na + static_cast<std::size_t>(n)];
  q.w_ = packed[na + static_cast<std::size_t>(n) + 1];
  return q;
}

void Quadric::add_to_packed(double* packed) const {
  const std::size_t na = static_cast<std::size_t>(n_ * (n_ + 1) / 2);
  for (std::size_t i = 0; i < na; ++i) packed[i] += a_[i];
  for (std::size_t i = 0; i < static_cast<std::size_t>(n_); ++i) packed[na + i] += b_[i];
  packed[na + static_cast<std::size_t>(n_)] += c_;
  packed[na + static_cast<std::size_t>(n_) + 1] += w_;
}

double Quadric::evaluate_packed(const double* q, int n, const double* v) {
  // Packed rows of A: row i holds A(i, i..n-1).
  const double* b = q + n * (n + 1) / 2;
  double s = b[n];
  const double* row = q;
  for (int i = 0; i < n; ++i) {
    double r = row[0] * v[i];
    for (int j = i + 1; j < n; ++j) r += 2.0 * row[j - i] * v[j];
    s += v[i] * r + 2.0 * b[i] * v[i];
    row += n - i;
  }
  return s > 0 ? s : 0.0;
}

bool Quadric::minimise_packed(const double* q, int n, double* v) {
  if (n == 3) {
    // Closed form for positions only: Cramer's rule on the 3x3 system A v = -b, refused
    // when det A is tiny against the cube of the mean diagonal (flat/straight neighbourhood).
    const double a00 = q[0], a01 = q[1], a02 = q[2], a11 = q[3], a12 = q[4], a22 = q[5];
    const double b0 = -q[6], b1 = -q[7], b2 = -q[8];
    const double c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11;
    const double det = a00 * c00 + a01 * c01 + a02 * c02;
    const double tr = (a00 + a11 + a22) / 3;
    if (!(tr > 0) || !(std::abs(det) > 1e-8 * tr * tr * tr)) return false;
    const double c11 = a00 * a22 - a02 * a02, c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01;
    v[0] = (c00 * b0 + c01 * b1 + c02 * b2) / det;
    v[1] = (c01 * b0 + c11 * b1 + c12 * b2) / det;
    v[2] = (c02 * b0 + c12 * b1 + c22 * b2) / det;
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
  }
  return unpack(q, n).minimise(v);
}

double Quadric::evaluate(const double* v) const {
  double s = c_;
  for (int i = 0; i < n_; ++i) {
    double row = a_[index(i, i)] * v[i];
    for (int j = i + 1; j < n_; ++j) row += 2.0 * a_[index(i, j)] * v[j];
    s += v[i] * row + 2.0 * b_[static_cast<std::size_t>(i)] * v[i];
  }
  return s > 0 ? s : 0.0;
}

bool Quadric::minimise(double* v) const {
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, max_dimension, max_dimension>;
  using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_dimension, 1>;
  Mat m(n_, n_);
  Vec rhs(n_);
  double trace = 0;
  for (int i = 0; i < n_; ++i) {
    for (int j = 0; j < n_; ++j) m(i, j) = a(i, j);
    rhs(i) = -b_[static_cast<std::size_t>(i)];
    trace += m(i, i);
  }
  if (!(trace > 0)) return false;
  // A is positive semi-definite; a pivot below 1e-8 of the mean diagonal means the planes
  // do not pin the point down in some direction (a flat or straight neighbourhood).
  Eigen::LDLT<Mat> ldlt(m);
  if (ldlt.info() != Eigen::Success) return false;
  const double floor_pivot = 1e-8 * trace / n_;
  const auto d = ldlt.vectorD();
  for (int i = 0; i < n_; ++i)
    if (!(d(i) > floor_pivot)) return false;
  const Vec x = ldlt.solve(rhs);
  for (int i = 0; i < n_; ++i) {
    if (!std::isfinite(x(i))) return false;
    v[i] = x(i);
  }
  return true;
}

}  // namespace fest::decimate
