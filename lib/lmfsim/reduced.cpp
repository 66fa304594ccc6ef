#include "lmfsim/reduced.hpp"

#include <cmath>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "core/error.hpp"

namespace fest::lmfsim {
namespace {

// a_ki of the reduced references (docs/lmfsim.md §5): how link i's angle moves link k's COM.
double weight(const ReducedChain& ch, int k, int i) {
  if (i < k) return 1;
  if (i == k) return ch.links[static_cast<std::size_t>(k)].com;
  return 0;
}

}  // namespace

Eigen::MatrixXd ReducedChain::mass_matrix(const Eigen::VectorXd& th) const {
  const int n = static_cast<int>(links.size());
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double mu = 0;
      for (int k = 0; k < n; ++k) mu += links[static_cast<std::size_t>(k)].mass * weight(*this, k, i) * weight(*this, k, j);
      M(i, j) = mu * links[static_cast<std::size_t>(i)].length * links[static_cast<std::size_t>(j)].length * std::cos(th[i] - th[j]);
      if (i == j) M(i, j) += links[static_cast<std::size_t>(i)].inertia;
    }
  return M;
}

Eigen::VectorXd ReducedChain::acceleration(const Eigen::VectorXd& th, const Eigen::VectorXd& thd) const {
  const int n = static_cast<int>(links.size());
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    const double li = links[static_cast<std::size_t>(i)].length;
    double h = 0, mg = 0;
    for (int j = 0; j < n; ++j) {
      double mu = 0;
      for (int k = 0; k < n; ++k) mu += links[static_cast<std::size_t>(k)].mass * weight(*this, k, i) * weight(*this, k, j);
      h += mu * li * links[static_cast<std::size_t>(j)].length * std::sin(th[i] - th[j]) * thd[j] * thd[j];
    }
    for (int k = 0; k < n; ++k) mg += links[static_cast<std::size_t>(k)].mass * weight(*this, k, i);
    rhs[i] = -h - g * li * std::sin(th[i]) * mg;
  }
  return mass_matrix(th).ldlt().solve(rhs);
}

Eigen::Vector2d ReducedChain::com_position(const Eigen::VectorXd& th, int i) const {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  for (int k = 0; k <= i; ++k) {
    const double l = links[static_cast<std::size_t>(k)].length * (k == i ? links[static_cast<std::size_t>(k)].com : 1.0);
    p += l * Eigen::Vector2d(std::sin(th[k]), -std::cos(th[k]));
  }
  return p;
}

Eigen::Vector2d ReducedChain::com_velocity(const Eigen::VectorXd& th, const Eigen::VectorXd& thd, int i) const {
  Eigen::Vector2d v = Eigen::Vector2d::Zero();
  for (int k = 0; k <= i; ++k) {
    const double l = links[static_cast<std::size_t>(k)].length * (k == i ? links[static_cast<std::size_t>(k)].com : 1.0);
    v += l * thd[k] * Eigen::Vector2d(std::cos(th[k]), std::sin(th[k]));
  }
  return v;
}

double ReducedChain::energy(const Eigen::VectorXd& th, const Eigen::VectorXd& thd) const {
  double e = 0;
  for (int i = 0; i < static_cast<int>(links.size()); ++i) {
    const ChainLink& L = links[static_cast<std::size_t>(i)];
    e += 0.5 * L.mass * com_velocity(th, thd, i).squaredNorm() + 0.5 * L.inertia * thd[i] * thd[i];
    e += L.mass * g * com_position(th, i).y();
  }
  return e;
}

void ReducedChain::step_rk4(Eigen::VectorXd& th, Eigen::VectorXd& thd, double h) const {
  const Eigen::VectorXd k1x = thd, k1v = acceleration(th, thd);
  const Eigen::VectorXd k2x = thd + 0.5 * h * k1v, k2v = acceleration(th + 0.5 * h * k1x, k2x);
  const Eigen::VectorXd k3x = thd + 0.5 * h * k2v, k3v = acceleration(th + 0.5 * h * k2x, k3x);
  const Eigen::VectorXd k4x = thd + h * k3v, k4v = acceleration(th + h * k3x, k4x);
  th += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
  thd += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
}

int FourBar::branch_of(const Eigen::Vector2d& A, const Eigen::Vector2d& B, const Eigen::Vector2d& D) {
  const Eigen::Vector2d u = B - A, w = D - A;
  return u.x() * w.y() - u.y() * w.x() >= 0 ? 1 : -1;
}

FourBar::Pose FourBar::pose(double phi) const {
  Pose p;
  const Eigen::Vector2d D(d, 0);
  p.A = a * Eigen::Vector2d(std::cos(phi), std::sin(phi));
  // B on the circles |B - A| = b and |B - D| = c.
  const Eigen::Vector2d AD = D - p.A;
  const double L = AD.norm();
  const double x = (b * b - c * c + L * L) / (2 * L);
  const double h2 = b * b - x * x;
  if (!(h2 >= 0) || L == 0) throw runtime_failure("four-bar cannot close at crank angle {:.6g}", phi);
  const Eigen::Vector2d e = AD / L, n(-e.y(), e.x());
  const double hh = std::sqrt(h2);
  // cross(B - A, D - A) = cross(x e + s h n, L e) = -s h L: branch +1 means s = -1.
  p.B = p.A + x * e - static_cast<double>(branch) * hh * n;
  p.angle[0] = phi;
  p.angle[1] = std::atan2(p.B.y() - p.A.y(), p.B.x() - p.A.x());
  p.angle[2] = std::atan2(p.B.y() - D.y(), p.B.x() - D.x());
  p.com[0] = 0.5 * p.A;
  p.com[1] = 0.5 * (p.A + p.B);
  p.com[2] = 0.5 * (D + p.B);
  return p;
}

// Kinematic coefficients (velocities per unit crank rate) in closed form: B lies on both
// circles, so (B - A).(B' - A') = 0 and (B - D).B' = 0, a 2x2 linear system for B'.
namespace {
struct Coefficients {
  Eigen::Vector2d com[3];
  double angle[3];
};
double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }
Coefficients coefficients(const FourBar& fb, const FourBar::Pose& p) {
  const Eigen::Vector2d D(fb.d, 0);
  const Eigen::Vector2d Ad(-p.A.y(), p.A.x());  // dA/dphi
  const Eigen::Vector2d u = p.B - p.A, w = p.B - D;
  Eigen::Matrix2d K;
  K << u.x(), u.y(), w.x(), w.y();
  const Eigen::Vector2d Bd = K.inverse() * Eigen::Vector2d(u.dot(Ad), 0.0);
  Coefficients c;
  c.com[0] = 0.5 * Ad;
  c.com[1] = 0.5 * (Ad + Bd);
  c.com[2] = 0.5 * Bd;
  c.angle[0] = 1;
  c.angle[1] = cross2(u, Bd - Ad) / u.squaredNorm();
  c.angle[2] = cross2(w, Bd) / w.squaredNorm();
  return c;
}
}  // namespace

double FourBar::mass(double phi) const {
  const Coefficients k = coefficients(*this, pose(phi));
  double M = 0;
  for (int i = 0; i < 3; ++i) M += m[i] * k.com[i].squaredNorm() + J[i] * k.angle[i] * k.angle[i];
  return M;
}

double FourBar::potential(double phi) const {
  const Pose p = pose(phi);
  double V = 0;
  for (int i = 0; i < 3; ++i) V += m[i] * g * p.com[i].y();
  return V;
}

double FourBar::acceleration(double phi, double phid) const {
  // M(phi) phi_dd + 1/2 M'(phi) phi_d^2 + V'(phi) = 0; V' from the coefficients, M' by
  // a central difference of the closed-form M.
  const double eps = 1e-5;
  const double dM = (mass(phi + eps) - mass(phi - eps)) / (2 * eps);
  const Coefficients k = coefficients(*this, pose(phi));
  double dV = 0;
  for (int i = 0; i < 3; ++i) dV += m[i] * g * k.com[i].y();
  return -(0.5 * dM * phid * phid + dV) / mass(phi);
}

void FourBar::step_rk4(double& phi, double& phid, double h) const {
  const double k1x = phid, k1v = acceleration(phi, phid);
  const double k2x = phid + 0.5 * h * k1v, k2v = acceleration(phi + 0.5 * h * k1x, k2x);
  const double k3x = phid + 0.5 * h * k2v, k3v = acceleration(phi + 0.5 * h * k2x, k3x);
  const double k4x = phid + h * k3v, k4v = acceleration(phi + h * k3x, k4x);
  phi += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
  phid += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
}

}  // namespace fest::lmfsim
