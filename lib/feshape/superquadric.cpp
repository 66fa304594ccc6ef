#include "feshape/superquadric.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <unsupported/Eigen/AutoDiff>

namespace fest::feshape {
namespace {

constexpr double pi = 3.14159265358979323846;

inline double value_of(double x) { return x; }
template <typename D>
double value_of(const Eigen::AutoDiffScalar<D>& x) { return x.value(); }

// sgn(x)|x|^e (the S^e, C^e of eq. 2). At x = 0 the value is 0 and so is every
// derivative: d/de (|x|^e) = |x|^e ln|x| -> 0, and the convention 0 ln 0 = 0 is applied.
template <typename T>
T signed_power(const T& x, const T& e) {
  using std::abs;
  using std::exp;
  using std::log;
  const double xv = value_of(x);
  if (xv == 0.0) return T(0.0) * e;  // a zero that carries zero derivatives of the right size
  const T magnitude = exp(e * log(abs(x)));
  return xv > 0 ? magnitude : T(-magnitude);
}

// Eq. 2 and eq. 3 for any scalar type: q are the 11 globals, (u, v) the material point.
template <typename T>
Eigen::Matrix<T, 3, 1> deformed_superquadric(const T* q, const T& u, const T& v) {
  using std::cos;
  using std::sin;
  const T& a = q[ia];
  const T cu = signed_power(T(cos(u)), q[ie1]);
  const T su = signed_power(T(sin(u)), q[ie1]);
  const T cv = signed_power(T(cos(v)), q[ie2]);
  const T sv = signed_power(T(sin(v)), q[ie2]);
  const T e1 = a * q[ia1] * cu * cv;
  const T e2 = a * q[ia2] * cu * sv;
  const T e3 = a * q[ia3] * su;
  // e3 / (a a3) = S_u^e1: the position along axis 3 in [-1, 1].
  const T z = su;
  Eigen::Matrix<T, 3, 1> s;
  s[0] = (q[it1] * z + 1.0) * e1 + q[ib1] * cos((z + q[ib2]) * pi * q[ib3]);
  s[1] = (q[it2] * z + 1.0) * e2;
  s[2] = e3;
  return s;
}

}  // namespace

const std::array<const char*, n_global>& global_names() {
  static const std::array<const char*, n_global> names{"a", "a1", "a2", "a3", "e1", "e2", "t1", "t2", "b1", "b2", "b3"};
  return names;
}

std::string check_global(const GlobalParams& q) {
  for (int i = 0; i < n_global; ++i)
    if (!std::isfinite(q[i])) return fmt::format("{} = {} is not finite", global_names()[i], q[i]);
  if (!(q[ia] > 0)) return fmt::format("a = {} must be > 0", q[ia]);
  for (int i : {ia1, ia2, ia3})
    if (!(q[i] > 0 && q[i] <= 1)) return fmt::format("{} = {} must be in (0, 1]", global_names()[i], q[i]);
  for (int i : {ie1, ie2})
    if (!(q[i] > 0)) return fmt::format("{} = {} must be > 0", global_names()[i], q[i]);
  for (int i : {it1, it2, ib2})
    if (!(std::abs(q[i]) <= 1)) return fmt::format("{} = {} must be in [-1, 1]", global_names()[i], q[i]);
  if (!(q[ib3] >= 0 && q[ib3] <= 1)) return fmt::format("b3 = {} must be in [0, 1]", q[ib3]);
  return {};
}

void clamp_global(GlobalParams& q) {
  q[ia] = std::max(q[ia], 1e-9);
  // s depends on a and a_i only through the semi-axes a a_i (and e3/(a a3) = S_u^e1), so
  // an a_i above 1 is folded into a: the same shape, with max a_i = 1 (the gauge that
  // keeps the representation unique and the steps unclipped).
  const double largest = std::max({q[ia1], q[ia2], q[ia3]});
  if (largest > 1) {
    q[ia] *= largest;
    for (int i : {ia1, ia2, ia3}) q[i] /= largest;
  }
  for (int i : {ia1, ia2, ia3}) q[i] = std::clamp(q[i], 1e-3, 1.0);
  for (int i : {ie1, ie2}) q[i] = std::clamp(q[i], 0.1, 4.0);
  for (int i : {it1, it2, ib2}) q[i] = std::clamp(q[i], -1.0, 1.0);
  q[ib3] = std::clamp(q[ib3], 0.0, 1.0);
}

Eigen::Vector3d shape(const GlobalParams& q, double u, double v) { return deformed_superquadric<double>(q.data(), u, v); }

Eigen::Matrix<double, 3, n_global> shape_jacobian(const GlobalParams& q, double u, double v) {
  using Derivatives = Eigen::Matrix<double, n_global, 1>;
  using Scalar = Eigen::AutoDiffScalar<Derivatives>;
  std::array<Scalar, n_global> qa;
  for (int i = 0; i < n_global; ++i) qa[i] = Scalar(q[i], n_global, i);
  const Eigen::Matrix<Scalar, 3, 1> s = deformed_superquadric<Scalar>(qa.data(), Scalar(u), Scalar(v));
  Eigen::Matrix<double, 3, n_global> j;
  for (int r = 0; r < 3; ++r) j.row(r) = s[r].derivatives().transpose();
  return j;
}

Eigen::Matrix<double, 3, 2> shape_tangents(const GlobalParams& q, double u, double v) {
  using Derivatives = Eigen::Matrix<double, 2, 1>;
  using Scalar = Eigen::AutoDiffScalar<Derivatives>;
  std::array<Scalar, n_global> qa;
  for (int i = 0; i < n_global; ++i) qa[i] = Scalar(q[i], Derivatives::Zero());
  const Eigen::Matrix<Scalar, 3, 1> s = deformed_superquadric<Scalar>(qa.data(), Scalar(u, 2, 0), Scalar(v, 2, 1));
  Eigen::Matrix<double, 3, 2> t;
  for (int r = 0; r < 3; ++r) t.row(r) = s[r].derivatives().transpose();
  return t;
}

}  // namespace fest::feshape
