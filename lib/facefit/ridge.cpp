#include "facefit/ridge.hpp"

#include <cmath>
#include <limits>

#include <Eigen/QR>
#include <Eigen/SVD>

#include "core/error.hpp"

namespace fest::facefit {

RidgeSolver::RidgeSolver(const Eigen::MatrixXd& Q, const Eigen::VectorXd& r, const Eigen::MatrixXd& T, double eps_rank)
    : l_(Q.rows()), Q_(Q), T_(T), r_(r) {
  if (!Q.allFinite()) throw bad_input("non-finite values in the measurement matrix");
  Eigen::MatrixXd Qp = Q;
  if (T.cols() > 0) {
    // Rank-revealing QR drops zero or collinear nuisance columns (L s_tz = 0 in frontal view).
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(T);
    qr.setThreshold(1e-10);
    q_ = qr.rank();
    Tbasis_ = (qr.householderQ() * Eigen::MatrixXd::Identity(l_, T.cols())).leftCols(q_);
    Qp -= Tbasis_ * (Tbasis_.transpose() * Q);
  }
  Eigen::BDCSVD<Eigen::MatrixXd> svd(Qp, Eigen::ComputeThinU | Eigen::ComputeThinV);
  U_ = svd.matrixU();
  V_ = svd.matrixV();
  w_ = svd.singularValues();
  const double w1 = w_.size() > 0 ? w_(0) : 0.0;
  rank_ = 0;
  while (rank_ < w_.size() && w_(rank_) > eps_rank * w1) ++rank_;
  if (rank_ == 0) throw runtime_failure("all singular values of Q are zero: the landmarks see no model variation");
  for (Eigen::Index i = rank_; i < w_.size(); ++i) w_(i) = 0;  // the threshold of eq. 17
  set_measurement(r);
}

void RidgeSolver::set_measurement(const Eigen::VectorXd& r) {
  if (r.size() != l_) throw bad_input("measurement has {} components, Q has {} rows", r.size(), l_);
  if (!r.allFinite()) throw bad_input("non-finite values in the measurement");
  r_ = r;
  Eigen::VectorXd rp = r;
  if (q_ > 0) rp -= Tbasis_ * (Tbasis_.transpose() * r);
  Utr_ = U_.transpose() * rp;
  for (Eigen::Index i = rank_; i < Utr_.size(); ++i) Utr_(i) = 0;
  perp_residual2_ = std::max(0.0, rp.squaredNorm() - Utr_.head(rank_).squaredNorm());
}

Eigen::VectorXd RidgeSolver::coefficients(double eta) const {
  Eigen::VectorXd factor(w_.size());
  for (Eigen::Index i = 0; i < w_.size(); ++i) {
    const double denom = w_(i) * w_(i) + eta;
    factor(i) = denom > 0 && w_(i) > 0 ? w_(i) / denom * Utr_(i) : 0.0;  // footnote 4
  }
  return V_ * factor;
}

Eigen::VectorXd RidgeSolver::nuisance(const Eigen::VectorXd& c) const {
  if (T_.cols() == 0) return Eigen::VectorXd();
  return T_.colPivHouseholderQr().solve(r_ - Q_ * c);
}

double RidgeSolver::residual_norm(double eta) const {
  const Eigen::VectorXd c = coefficients(eta);
  Eigen::VectorXd res = Q_ * c - r_;
  if (T_.cols() > 0) res += T_ * nuisance(c);
  return res.norm();
}

double RidgeSolver::effective_dof(double eta) const {
  double dof = 0;
  for (Eigen::Index i = 0; i < rank_; ++i) dof += w_(i) * w_(i) / (w_(i) * w_(i) + eta);
  return dof;
}

double RidgeSolver::gcv(double eta) const {
  // The residual in the rotated frame: components along u_i shrink by η/(w_i²+η).
  double res2 = perp_residual2_;
  for (Eigen::Index i = 0; i < rank_; ++i) {
    const double f = eta / (w_(i) * w_(i) + eta);
    res2 += f * f * Utr_(i) * Utr_(i);
  }
  const double lp = static_cast<double>(l_ - q_);
  const double denom = lp - effective_dof(eta);
  if (denom <= 0) return std::numeric_limits<double>::infinity();
  return lp * res2 / (denom * denom);
}

double RidgeSolver::neg2_log_evidence(double eta) const {
  // r' ~ N(0, Q'Q'^T + η I) in the (l − q)-dimensional complement of range(T).
  double v = 0;
  for (Eigen::Index i = 0; i < rank_; ++i) {
    const double d = w_(i) * w_(i) + eta;
    v += Utr_(i) * Utr_(i) / d + std::log(d);
  }
  const double rest = static_cast<double>(l_ - q_ - rank_);
  v += rest * std::log(eta) + perp_residual2_ / eta;
  return v;
}

double RidgeSolver::minimise_log_eta(double (RidgeSolver::*objective)(double) const) const {
  const double w1sq = w_(0) * w_(0);
  const double lo = std::log(1e-8 * w1sq), hi = std::log(1e4 * w1sq);
  // Coarse scan first (both criteria can have several local minima), then golden
  // section in the bracket around the best grid point.
  const int steps = 96;
  int best = 0;
  double best_value = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i) {
    const double value = (this->*objective)(std::exp(lo + (hi - lo) * i / steps));
    if (value < best_value) {
      best_value = value;
      best = i;
    }
  }
  double a = lo + (hi - lo) * std::max(0, best - 1) / steps;
  double b = lo + (hi - lo) * std::min(steps, best + 1) / steps;
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = (this->*objective)(std::exp(x1)), f2 = (this->*objective)(std::exp(x2));
  for (int it = 0; it < 60; ++it) {
    if (f1 < f2) {
      b = x2; x2 = x1; f2 = f1;
      x1 = b - g * (b - a); f1 = (this->*objective)(std::exp(x1));
    } else {
      a = x1; x1 = x2; f1 = f2;
      x2 = a + g * (b - a); f2 = (this->*objective)(std::exp(x2));
    }
  }
  return std::exp((a + b) / 2);
}

double RidgeSolver::eta_by_gcv() const { return minimise_log_eta(&RidgeSolver::gcv); }
double RidgeSolver::eta_by_evidence() const { return minimise_log_eta(&RidgeSolver::neg2_log_evidence); }

}  // namespace fest::facefit
