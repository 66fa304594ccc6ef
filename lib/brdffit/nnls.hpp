#pragma once
// Non-negative least squares, min |A x - b| subject to x >= 0, by the active-set method of
// Lawson and Hanson (Solving Least Squares Problems, 1974, ch. 23): the non-negative weights of the projection.

#include <Eigen/Core>

namespace fest::brdffit {

Eigen::VectorXd nnls(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, int max_iterations = 0);

}  // namespace fest::brdffit
