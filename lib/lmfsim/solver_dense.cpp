// Reference solver: A = J M^-1 J^T assembled block by block (only constraint pairs that
// share a body contribute), Cholesky, truncated SVD when the pivots say A is singular.
#include <cmath>

#include <Eigen/Cholesky>

#include "lmfsim/solver.hpp"

namespace fest::lmfsim {
namespace {

class DenseSolver final : public Solver {
 public:
  explicit DenseSolver(double tol) : tol_(tol) {}

  void solve(const std::vector<SolveBody>& bodies, const std::vector<SolveConstraint>& cons, bool,
             SolveResult& out) override {
    const std::size_t nb = bodies.size(), nc = cons.size();
    offset_.assign(nc + 1, 0);
    for (std::size_t j = 0; j < nc; ++j) offset_[j + 1] = offset_[j] + cons[j].rows();
    const int m = offset_[nc];
    // Which constraint touches which body, with the side's Jacobian.
    touching_.assign(nb, {});
    for (std::size_t j = 0; j < nc; ++j) {
      if (cons[j].a >= 0) touching_[static_cast<std::size_t>(cons[j].a)].push_back({j, cons[j].Ja});
      if (cons[j].b >= 0) touching_[static_cast<std::size_t>(cons[j].b)].push_back({j, cons[j].Jb});
    }
    A_.setZero(m, m);
    rhs_.resize(m);
    for (std::size_t j = 0; j < nc; ++j) rhs_.segment(offset_[j], cons[j].rows()) = -cons[j].c;
    for (std::size_t i = 0; i < nb; ++i) {
      const SolveBody& B = bodies[i];
      const Vecx MinvF = B.Minv * B.F;
      for (const auto& [j, Jj] : touching_[i]) {
        const int rj = cons[j].rows();
        const Blk Jjb = Jj->leftCols(B.dof);
        rhs_.segment(offset_[j], rj) -= Jjb * MinvF;
        const Blk JM = Jjb * B.Minv;
        for (const auto& [k, Jk] : touching_[i])
          A_.block(offset_[j], offset_[k], rj, cons[k].rows()) += JM * Jk->leftCols(B.dof).transpose();
      }
    }
    out.rank_deficiency = 0;
    // Cholesky (blocked, no pivoting: A is SPD for independent rows); a pivot ratio
    // below 1e-12 means redundant rows, answered by the truncated SVD.
    llt_.compute(A_);
    bool singular = m > 0 && llt_.info() != Eigen::Success;
    if (m > 0 && !singular) {
      const auto d = llt_.matrixLLT().diagonal().cwiseAbs2();
      singular = d.minCoeff() < 1e-12 * d.maxCoeff();
    }
    if (m == 0) {
      lambda_.resize(0);
    } else if (!singular) {
      lambda_ = llt_.solve(rhs_);
    } else {
      out.rank_deficiency = truncated_svd_solve(A_, rhs_, tol_, lambda_);
    }
    const double scale = std::max(rhs_.size() ? rhs_.cwiseAbs().maxCoeff() : 0.0, 1e-9);
    out.residual = m ? (A_ * lambda_ - rhs_).cwiseAbs().maxCoeff() / scale : 0.0;
    out.lambda.resize(nc);
    for (std::size_t j = 0; j < nc; ++j) out.lambda[j] = lambda_.segment(offset_[j], cons[j].rows());
    out.acc.resize(nb);
    for (std::size_t i = 0; i < nb; ++i) {
      Vecx f = bodies[i].F;
      for (const auto& [j, Jj] : touching_[i]) f += Jj->leftCols(bodies[i].dof).transpose() * out.lambda[j];
      out.acc[i] = bodies[i].Minv * f;
    }
  }

 private:
  double tol_;
  std::vector<int> offset_;
  std::vector<std::vector<std::pair<std::size_t, const Blk*>>> touching_;
  Eigen::MatrixXd A_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::VectorXd rhs_, lambda_;
};

}  // namespace

std::unique_ptr<Solver> make_dense_solver(double svd_tol) { return std::make_unique<DenseSolver>(svd_tol); }

}  // namespace fest::lmfsim
