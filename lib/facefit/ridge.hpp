#pragma once
// The chapter's estimator (docs/facefit.md §2, eq. 29-39): minimise ‖Q c + T t − r‖² + η ‖c‖²
// over the standardised coefficients c (penalised) and nuisance parameters t (free,
// e.g. translation and scale, eq. 49-50). T is eliminated by projecting onto the
// orthogonal complement of its range, P⊥ = I − T T⁺; then one SVD P⊥Q = U W V^T serves
// every η:   c(η) = V diag(w_i / (w_i² + η)) U^T P⊥ r                          (eq. 39)
// and t = T⁺ (r − Q c). Automatic η by GCV or maximum evidence (docs/facefit.md §2, §4).

#include <Eigen/Core>

namespace fest::facefit {

class RidgeSolver {
 public:
  // Q: l×k, r: l, T: l×q (q may be 0). eps_rank: w_i ≤ eps_rank·w_1 count as zero.
  RidgeSolver(const Eigen::MatrixXd& Q, const Eigen::VectorXd& r, const Eigen::MatrixXd& T = Eigen::MatrixXd(),
              double eps_rank = 1e-10);

  // Replaces r, keeping Q, T and the SVD (a new measurement costs O(l·k), not an SVD).
  void set_measurement(const Eigen::VectorXd& r);

  Eigen::VectorXd coefficients(double eta) const;              // c(η)
  Eigen::VectorXd nuisance(const Eigen::VectorXd& c) const;    // t = T⁺ (r − Q c)
  double residual_norm(double eta) const;                       // E_r = ‖Qc + Tt − r‖
  double effective_dof(double eta) const;                       // Σ w²/(w²+η)
  double gcv(double eta) const;                                 // l'‖res‖² / (l' − dof)²
  double neg2_log_evidence(double eta) const;                   // −2 log p(r | η), up to a constant
  double eta_by_gcv() const;
  double eta_by_evidence() const;

  const Eigen::VectorXd& singular_values() const { return w_; }  // all min(l,k) of them, descending
  Eigen::Index rank() const { return rank_; }
  const Eigen::MatrixXd& V() const { return V_; }
  Eigen::Index rows() const { return l_; }
  Eigen::Index nuisance_columns() const { return q_; }

 private:
  double minimise_log_eta(double (RidgeSolver::*objective)(double) const) const;

  Eigen::Index l_ = 0, q_ = 0, rank_ = 0;
  Eigen::MatrixXd Q_, T_;
  Eigen::VectorXd r_;
  Eigen::MatrixXd Tbasis_;   // orthonormal basis of range(T), l×q
  Eigen::MatrixXd U_, V_;    // thin SVD of P⊥Q
  Eigen::VectorXd w_;
  Eigen::VectorXd Utr_;      // U^T P⊥ r
  double perp_residual2_ = 0;  // ‖P⊥r − U U^T P⊥r‖² over the kept columns (invisible to the model)
};

}  // namespace fest::facefit
