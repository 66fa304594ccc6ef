// Model building (docs/facefit.md §1): mean, orthonormal basis, the training
// set's mean squared Mahalanobis norm equal to k, independence of example order.

#include <algorithm>
#include <numeric>

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "facefit/pca_build.hpp"
#include "facefit_fixtures.hpp"

using namespace facefit_test;

namespace {

Eigen::MatrixXd g1_examples(std::size_t m, std::uint64_t seed) {
  const Model g1 = g1_model();
  Rng rng(seed);
  Eigen::MatrixXd X(1200, static_cast<Eigen::Index>(m));
  for (std::size_t i = 0; i < m; ++i) X.col(static_cast<Eigen::Index>(i)) = reconstruct(g1, random_coefficients(rng, 30));
  return X;
}

}  // namespace

TEST(FacefitPca, MeanBasisAndMahalanobisNorms) {
  const Eigen::MatrixXd X = g1_examples(50, 7);
  BuildOptions o;
  o.float_basis = false;
  const Model m = build_model(X, 3, o);
  EXPECT_EQ(m.components, 30u);  // rank of 50 draws from a 30-dim model
  EXPECT_EQ(m.training_examples, 50u);
  const Eigen::VectorXd mean = X.rowwise().mean();
  for (Eigen::Index i = 0; i < mean.size(); ++i) EXPECT_NEAR(m.mean[static_cast<std::size_t>(i)], mean(i), 1e-6);
  const Eigen::MatrixXd S = basis_matrix(m);
  EXPECT_LT((S.transpose() * S - Eigen::MatrixXd::Identity(30, 30)).cwiseAbs().maxCoeff(), 1e-6);
  for (std::size_t i = 1; i < m.sigma.size(); ++i) EXPECT_GE(m.sigma[i - 1], m.sigma[i]);
  // (1/m) Σ_j ‖c_j‖² = k: the covariance is 1/m X X^T, so the standardised coefficients
  // of the training set have unit mean square in every direction.
  double sum = 0;
  for (Eigen::Index j = 0; j < X.cols(); ++j) sum += coefficients_of(m, X.col(j)).squaredNorm();
  EXPECT_NEAR(sum / 50.0, 30.0, 30.0 * 1e-5);
}

TEST(FacefitPca, ShuffledExamplesGiveTheSameModel) {
  const Eigen::MatrixXd X = g1_examples(50, 9);
  std::vector<Eigen::Index> order(50);
  std::iota(order.begin(), order.end(), 0);
  Rng rng(3);
  for (std::size_t i = order.size() - 1; i > 0; --i) std::swap(order[i], order[static_cast<std::size_t>(rng.below(i + 1))]);
  Eigen::MatrixXd Y(X.rows(), X.cols());
  for (Eigen::Index j = 0; j < 50; ++j) Y.col(j) = X.col(order[static_cast<std::size_t>(j)]);
  BuildOptions o;
  o.float_basis = false;
  const Model a = build_model(X, 3, o), b = build_model(Y, 3, o);
  ASSERT_EQ(a.components, b.components);
  for (std::size_t i = 0; i < a.components; ++i) EXPECT_NEAR(a.sigma[i], b.sigma[i], 1e-6 * a.sigma[0]);
  // Same subspace: all principal angles ~0, i.e. singular values of A^T B are 1.
  const Eigen::VectorXd cosines = (basis_matrix(a).transpose() * basis_matrix(b)).jacobiSvd().singularValues();
  EXPECT_GT(cosines.minCoeff(), std::cos(1e-5));
}

TEST(FacefitPca, RankOfCentredDataIsAtMostMMinusOne) {
  // 10 examples of a 30-dim model: 9 components (the centred data lose one rank).
  const Eigen::MatrixXd X = g1_examples(10, 11);
  const Model m = build_model(X, 3, {});
  EXPECT_EQ(m.components, 9u);
  BuildOptions o;
  o.components = 4;
  EXPECT_EQ(build_model(X, 3, o).components, 4u);
}

TEST(FacefitPca, RejectsTooFewOrIdenticalExamples) {
  const Eigen::MatrixXd one = Eigen::MatrixXd::Ones(30, 1);
  EXPECT_THROW(build_model(one, 3, {}), fest::Error);
  const Eigen::MatrixXd same = Eigen::MatrixXd::Ones(30, 4);
  EXPECT_THROW(build_model(same, 3, {}), fest::Error);
}
