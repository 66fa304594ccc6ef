#pragma once
// Model building (docs/facefit.md §1, the chapter's section 1.2): mean, covariance C = (1/m) X X^T
// (1/m, not 1/(m-1)), PCA through the m×m Gram matrix because n ≫ m.

#include <cstddef>

#include <Eigen/Core>

#include "facefit/model.hpp"

namespace fest::facefit {

struct BuildOptions {
  std::size_t components = 0;  // keep at most this many (0 = all, m - 1 at most)
  double variance = 0;         // or: the fewest explaining this fraction of variance (0 = off)
  bool float_basis = true;     // store the basis as float32 (the .mmb default)
};

// examples: n×m, one registered shape per column (interleaved coordinates).
// Components with λ_i ≤ 1e-12 λ_1 are dropped. Throws bad_input for m < 2.
Model build_model(const Eigen::MatrixXd& examples, int dims, const BuildOptions& options);

}  // namespace fest::facefit
