#include "facefit/pca_build.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "core/error.hpp"

namespace fest::facefit {

Model build_model(const Eigen::MatrixXd& examples, int dims, const BuildOptions& options) {
  const Eigen::Index n = examples.rows();
  const Eigen::Index m = examples.cols();
  if (m < 2) throw bad_input("model building needs at least 2 examples, got {}", m);
  if (dims != 2 && dims != 3) throw usage_error("dims must be 2 or 3");
  if (n % dims != 0) throw bad_input("example length {} is not a multiple of {}", n, dims);
  if (!examples.allFinite()) throw bad_input("examples contain non-finite coordinates");

  Model model;
  model.dims = dims;
  model.points = static_cast<std::size_t>(n / dims);
  model.training_examples = static_cast<std::size_t>(m);
  const Eigen::VectorXd mean = examples.rowwise().mean();
  model.mean.assign(mean.data(), mean.data() + n);
  const Eigen::MatrixXd X = examples.colwise() - mean;

  // G = X^T X = V Λ V^T; σ_i = √(λ_i / m); s_i = X v_i / √λ_i.
  const Eigen::MatrixXd G = X.transpose() * X;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(G);
  if (eig.info() != Eigen::Success) throw runtime_failure("eigen-decomposition of the Gram matrix failed");
  const Eigen::VectorXd lambda = eig.eigenvalues().reverse();        // descending
  const Eigen::MatrixXd V = eig.eigenvectors().rowwise().reverse();
  const double lambda1 = lambda(0);
  if (!(lambda1 > 0)) throw bad_input("all examples are identical: no variance to model");
  Eigen::Index k = 0;
  while (k < m && lambda(k) > 1e-12 * lambda1) ++k;
  k = std::min<Eigen::Index>(k, m - 1);  // rank of centred data is at most m - 1
  if (options.variance > 0) {
    const double total = lambda.head(k).sum();
    double acc = 0;
    Eigen::Index keep = 0;
    while (keep < k && acc < options.variance * total) acc += lambda(keep++);
    k = std::max<Eigen::Index>(keep, 1);
  }
  if (options.components > 0) k = std::min<Eigen::Index>(k, static_cast<Eigen::Index>(options.components));

  Eigen::MatrixXd S = X * V.leftCols(k);
  model.components = static_cast<std::size_t>(k);
  model.sigma.resize(static_cast<std::size_t>(k));
  for (Eigen::Index i = 0; i < k; ++i) {
    S.col(i) /= std::sqrt(lambda(i));
    // One Gram-Schmidt pass against rounding in the product (columns are orthogonal in
    // exact arithmetic); keeps the basis orthonormal to ~1e-15.
    for (Eigen::Index j = 0; j < i; ++j) S.col(i) -= S.col(j).dot(S.col(i)) * S.col(j);
    S.col(i).normalize();
    model.sigma[static_cast<std::size_t>(i)] = std::sqrt(lambda(i) / static_cast<double>(m));
  }
  if (options.float_basis)
    set_owned_basis_f32(model, S);
  else
    set_owned_basis(model, S);
  return model;
}

}  // namespace fest::facefit
