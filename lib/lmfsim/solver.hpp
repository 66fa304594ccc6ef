#pragma once
// Solvers of the LMF system (docs/lmfsim.md §3): given M, F, J and c, find xdd and lambda with
//   M xdd = F + J^T lambda,   J xdd + c = 0.
// DenseSolver: assemble A = J M^-1 J^T, Cholesky, truncated-SVD fallback (reference).
// BaraffSolver: Baraff's O(n) block elimination on the KKT graph of a spanning forest
// of primary constraints, auxiliary rows through a k x k SVD-solved Schur complement.

#include <memory>
#include <vector>

#include "lmfsim/kinematics.hpp"

namespace fest::lmfsim {

struct SolveBody {
  int dof = 0;  // 3 or 6
  Blk M, Minv;  // dof x dof
  Vecx F;       // dof
};

struct SolveConstraint {
  int a = -1, b = -1;  // indices into the moving bodies, -1 = ground (world or fixed)
  const Blk* Ja = nullptr;  // rows x 6 (first dof columns used)
  const Blk* Jb = nullptr;
  Vecx c;                   // right-hand term: J xdd + c = 0
  int rows() const { return static_cast<int>(c.size()); }
};

struct SolveResult {
  std::vector<Vecx> acc;     // per moving body
  std::vector<Vecx> lambda;  // per constraint
  int rank_deficiency = 0;   // rows dropped by the truncated SVD
  double residual = 0;       // max abs(A lambda - rhs) over max(max abs rhs, 1e-9)
};

class Solver {
 public:
  virtual ~Solver() = default;
  // `topology_changed`: the (a, b) pattern of `cons` differs from the last call.
  virtual void solve(const std::vector<SolveBody>& bodies, const std::vector<SolveConstraint>& cons,
                     bool topology_changed, SolveResult& out) = 0;
};

std::unique_ptr<Solver> make_dense_solver(double svd_tol);
std::unique_ptr<Solver> make_baraff_solver(double svd_tol);

// Minimum-norm solution of the symmetric PSD system A x = b by an eigen/SVD
// decomposition, dropping singular values < tol * sigma_max. Returns the count dropped.
int truncated_svd_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double tol, Eigen::VectorXd& x);

// Partition of constraints into primary (spanning forest of the body graph, ground as
// one node) and auxiliary (loop closures, second ground attachments, redundancies).
std::vector<bool> primary_constraints(int n_bodies, const std::vector<SolveConstraint>& cons);

}  // namespace fest::lmfsim
