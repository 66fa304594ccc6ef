// The estimator (docs/facefit.md §2): eq. 39 against the normal
// equations, the minimum-norm pseudo-inverse, monotonicity in η, the L = id shrinkage,
// the nuisance elimination, automatic η.

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>
#include <gtest/gtest.h>

#include "facefit/fit.hpp"
#include "facefit/ridge.hpp"
#include "facefit_fixtures.hpp"

using namespace facefit_test;

namespace {

Eigen::MatrixXd random_matrix(Rng& rng, Eigen::Index r, Eigen::Index c) {
  Eigen::MatrixXd M(r, c);
  for (Eigen::Index i = 0; i < M.size(); ++i) M.data()[i] = rng.normal();
  return M;
}

Eigen::VectorXd random_vector(Rng& rng, Eigen::Index n) { return random_matrix(rng, n, 1); }

}  // namespace

TEST(FacefitRidge, Eq39EqualsNormalEquations) {
  Rng rng(1);
  const Eigen::MatrixXd Q = random_matrix(rng, 40, 25);
  const Eigen::VectorXd r = random_vector(rng, 40);
  const RidgeSolver solver(Q, r);
  for (double eta : {1e-6, 1.0, 1e3}) {
    // (Q^T Q + η I) c = Q^T r  (eq. 33), by LDLT in double.
    const Eigen::MatrixXd A = Q.transpose() * Q + eta * Eigen::MatrixXd::Identity(25, 25);
    const Eigen::VectorXd c_ref = A.ldlt().solve(Q.transpose() * r);
    const Eigen::VectorXd c = solver.coefficients(eta);
    EXPECT_LT((c - c_ref).norm() / c_ref.norm(), 1e-8) << "eta " << eta;
  }
}

TEST(FacefitRidge, EtaZeroIsTheMinimumNormPseudoInverse) {
  // k > l: Qc = r has many solutions; eq. 18 gives the one of least ‖c‖ (footnote 3).
  Rng rng(2);
  const Eigen::MatrixXd Q = random_matrix(rng, 12, 30);
  const Eigen::VectorXd r = random_vector(rng, 12);
  const RidgeSolver solver(Q, r);
  const Eigen::VectorXd c = solver.coefficients(0.0);
  EXPECT_LT((Q * c - r).norm(), 1e-9 * r.norm());
  const Eigen::VectorXd c_pinv = Q.completeOrthogonalDecomposition().pseudoInverse() * r;
  EXPECT_LT((c - c_pinv).norm(), 1e-9 * c_pinv.norm());
  // Adding null-space vectors keeps Qc = r and only lengthens c.
  const Eigen::MatrixXd N = Q.fullPivLu().kernel();
  for (int t = 0; t < 100; ++t) {
    const Eigen::VectorXd other = c + N * random_vector(rng, N.cols());
    EXPECT_LT((Q * other - r).norm(), 1e-8 * r.norm());
    EXPECT_GT(other.norm(), c.norm());
  }
}

TEST(FacefitRidge, ResidualGrowsAndNormShrinksWithEta) {
  // Ridge regression: E_r(η) non-decreasing, ‖c(η)‖ non-increasing (analytic property).
  Rng rng(3);
  const double etas[] = {0, 1e-6, 1e-4, 1e-2, 0.1, 1, 10, 100, 1e4, 1e6};
  for (int problem = 0; problem < 20; ++problem) {
    const Eigen::Index l = 10 + static_cast<Eigen::Index>(rng.below(40)), k = 5 + static_cast<Eigen::Index>(rng.below(40));
    const RidgeSolver solver(random_matrix(rng, l, k), random_vector(rng, l));
    double last_res = -1, last_norm = 1e300;
    for (double eta : etas) {
      const double res = solver.residual_norm(eta), norm = solver.coefficients(eta).norm();
      EXPECT_GE(res, last_res * (1 - 1e-9));
      EXPECT_LE(norm, last_norm * (1 + 1e-9));
      last_res = res;
      last_norm = norm;
    }
  }
}

TEST(FacefitRidge, NuisanceColumnsAreUnpenalised) {
  // min ‖Qc + Tt − r‖² + η‖c‖² equals the augmented normal equations with a zero block
  // on t.
  Rng rng(4);
  const Eigen::MatrixXd Q = random_matrix(rng, 30, 12), T = random_matrix(rng, 30, 3);
  const Eigen::VectorXd r = random_vector(rng, 30);
  const double eta = 0.7;
  const RidgeSolver solver(Q, r, T);
  const Eigen::VectorXd c = solver.coefficients(eta), t = solver.nuisance(c);
  Eigen::MatrixXd A(30, 15);
  A << Q, T;
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(15, 15);
  D.topLeftCorner(12, 12) = eta * Eigen::MatrixXd::Identity(12, 12);
  const Eigen::VectorXd x = (A.transpose() * A + D).ldlt().solve(A.transpose() * r);
  EXPECT_LT((c - x.head(12)).norm(), 1e-9 * x.norm());
  EXPECT_LT((t - x.tail(3)).norm(), 1e-9 * x.norm());
  // A zero or repeated nuisance column is dropped, not fatal.
  Eigen::MatrixXd T2(30, 4);
  T2 << T, Eigen::VectorXd::Zero(30);
  const RidgeSolver solver2(Q, r, T2);
  EXPECT_EQ(solver2.nuisance_columns(), 3);
  EXPECT_LT((solver2.coefficients(eta) - c).norm(), 1e-9 * c.norm());
}

TEST(FacefitRidge, EvidenceAndGcvFindTheNoiseVariance) {
  // Data from the model's own prior: c ~ N(0, I), r = Qc + noise σ_N. With many rows
  // the evidence maximum is close to σ_N²; GCV close too.
  Rng rng(5);
  for (double sigma_n : {0.1, 1.0}) {
    const Eigen::MatrixXd Q = 3 * random_matrix(rng, 400, 20);
    Eigen::VectorXd r = Q * random_vector(rng, 20);
    for (Eigen::Index i = 0; i < r.size(); ++i) r(i) += sigma_n * rng.normal();
    const RidgeSolver solver(Q, r);
    const double target = sigma_n * sigma_n;
    EXPECT_NEAR(std::log(solver.eta_by_evidence() / target), 0.0, std::log(1.5)) << sigma_n;
    EXPECT_NEAR(std::log(solver.eta_by_gcv() / target), 0.0, std::log(3.0)) << sigma_n;
  }
}

TEST(FacefitRidge, FullShapeShrinksEachComponent) {
  // L = id (eq. 44-46): component i of the result is ⟨s_i, r⟩ / (1 + η/σ_i²).
  const Model m = g1_model();
  Rng rng(6);
  Eigen::VectorXd shape = reconstruct(m, random_coefficients(rng, 30));
  for (Eigen::Index i = 0; i < shape.size(); ++i) shape(i) += 0.5 * rng.normal();  // leave the span
  const Eigen::MatrixXd S = basis_matrix(m);
  const Eigen::VectorXd d = shape - Eigen::Map<const Eigen::VectorXd>(m.mean.data(), 1200);
  for (double eta : {0.0, 1.0, 100.0}) {
    const Eigen::VectorXd out = fit_full_shape(m, shape, eta) - Eigen::Map<const Eigen::VectorXd>(m.mean.data(), 1200);
    const Eigen::VectorXd proj = S.transpose() * out;
    for (Eigen::Index i = 0; i < 30; ++i) {
      const double s2 = m.sigma[static_cast<std::size_t>(i)] * m.sigma[static_cast<std::size_t>(i)];
      EXPECT_NEAR(proj(i), S.col(i).dot(d) / (1 + eta / s2), 1e-9 * d.norm());
    }
    EXPECT_LT((out - S * proj).norm(), 1e-9 * d.norm());  // nothing outside the span
  }
  // η = 0 is an orthogonal projection: idempotent.
  const Eigen::VectorXd once = fit_full_shape(m, shape, 0.0);
  EXPECT_LT((fit_full_shape(m, once, 0.0) - once).cwiseAbs().maxCoeff(), 1e-6);
}
