#pragma once
// Downhill simplex (Nelder & Mead 1965) with the standard coefficients (reflection 1,
// expansion 2, contraction 1/2, shrink 1/2). Derivative-free: the silhouette XOR cost of
// registration (docs/brdffit.md §6) is piecewise constant, so gradients are of no use.

#include <functional>
#include <vector>

#include <Eigen/Core>

namespace fest::brdffit {

struct SimplexResult {
  Eigen::VectorXd x;
  double value = 0;
  int iterations = 0;
};

// Starts from x0 and the simplex x0 + step_i e_i; stops after max_iters iterations or when
// the spread of the simplex's values falls below f_tol (absolute) and its size below x_tol.
SimplexResult nelder_mead(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& x0,
                          const Eigen::VectorXd& step, int max_iters, double f_tol = 0, double x_tol = 1e-9);

}  // namespace fest::brdffit
