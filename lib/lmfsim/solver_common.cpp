#include <numeric>

#include <Eigen/SVD>

#include "lmfsim/solver.hpp"

namespace fest::lmfsim {

int truncated_svd_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double tol, Eigen::VectorXd& x) {
  x.setZero(b.size());
  if (b.size() == 0) return 0;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto& s = svd.singularValues();
  const double smax = s.size() ? s[0] : 0.0;
  int dropped = 0;
  Eigen::VectorXd ub = svd.matrixU().transpose() * b;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (s[i] > tol * smax && s[i] > 0) {
      ub[i] /= s[i];
    } else {
      ub[i] = 0;
      ++dropped;
    }
  }
  x = svd.matrixV() * ub;
  return dropped;
}

std::vector<bool> primary_constraints(int n_bodies, const std::vector<SolveConstraint>& cons) {
  // Union-find over bodies plus one virtual ground node (index n_bodies); a constraint
  // is primary when it joins two different trees.
  std::vector<int> parent(static_cast<std::size_t>(n_bodies) + 1);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
      parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
      i = parent[static_cast<std::size_t>(i)];
    }
    return i;
  };
  std::vector<bool> primary(cons.size(), false);
  for (std::size_t j = 0; j < cons.size(); ++j) {
    const int ra = find(cons[j].a < 0 ? n_bodies : cons[j].a), rb = find(cons[j].b < 0 ? n_bodies : cons[j].b);
    if (ra == rb) continue;
    parent[static_cast<std::size_t>(ra)] = rb;
    primary[j] = true;
  }
  return primary;
}

}  // namespace fest::lmfsim
