#include "ffd/joints.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "core/error.hpp"

namespace fest::ffd {

JointSolve preserve_joints(Lattice& lattice, const std::vector<Joint>& joints, const std::vector<std::size_t>& fixed) {
  JointSolve out;
  if (joints.empty()) return out;
  Deformer deformer(lattice);
  lattice.displacement = deformer.lattice().displacement;  // materialise zeros
  const std::size_t K = lattice.size(), C = joints.size();
  std::vector<char> is_fixed(K, 0);
  for (const std::size_t f : fixed) {
    if (f >= K) throw bad_input("fixed control point {} is outside the lattice ({} points)", f, K);
    is_fixed[f] = 1;
  }
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(C), static_cast<Eigen::Index>(K));
  std::vector<std::pair<std::size_t, double>> w;
  Eigen::MatrixXd r(static_cast<Eigen::Index>(C), 3);
  for (std::size_t c = 0; c < C; ++c) {
    if (!Deformer::inside(deformer.local(joints[c].rest)))
      throw bad_input("joint '{}' lies outside the lattice box", joints[c].name);
    if (!joints[c].target.allFinite()) throw bad_input("joint '{}' has a non-finite target", joints[c].name);
    deformer.weights(joints[c].rest, w);
    for (const auto& [k, v] : w)
      if (!is_fixed[k]) W(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(k)) = v;
    const Eigen::Vector3d now = deformer.apply(joints[c].rest);
    r.row(static_cast<Eigen::Index>(c)) = (joints[c].target - now).transpose();
    out.max_error_before = std::max(out.max_error_before, (joints[c].target - now).norm());
  }
  const Eigen::MatrixXd G = W * W.transpose();
  const double lambda = 1e-12 * G.trace() / static_cast<double>(C);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(W);
  out.rank = static_cast<int>(qr.rank());
  out.exact = out.rank == static_cast<int>(C);
  Eigen::MatrixXd Greg = G;
  Greg.diagonal().array() += lambda;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(Greg);
  Eigen::MatrixXd delta = W.transpose() * ldlt.solve(r);
  // One refinement step on the residual removes the bias of lambda.
  delta += W.transpose() * ldlt.solve(r - W * delta);
  for (std::size_t k = 0; k < K; ++k) lattice.displacement[k] += delta.row(static_cast<Eigen::Index>(k)).transpose();
  out.correction_norm = delta.norm();
  const Deformer after(lattice);
  for (const Joint& j : joints) out.max_error_after = std::max(out.max_error_after, (after.apply(j.rest) - j.target).norm());
  return out;
}

}  // namespace fest::ffd
