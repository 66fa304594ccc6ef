#pragma once
// Multigrid for one parity class of the projection (`--poisson mg`, the solver the seed
// compared pois3d against). Galerkin coarse operators A_c = P^T A P with tensor-product
// linear interpolation P, so the class's boundary rows (whole- and half-sample mirrors)
// need no special cases; V(2,2) cycles with symmetric Gauss-Seidel, a pseudo-inverse on
// the coarsest level, until the relative residual is below the tolerance.

#include <array>
#include <memory>
#include <vector>

#include "fluidsim/grid.hpp"
#include "fluidsim/spectral.hpp"

namespace fest::fluidsim {

class MultigridClass {
 public:
  MultigridClass(const Layout& layout, const std::array<std::shared_ptr<const AxisBasis>, 3>& axes, double tol);
  ~MultigridClass();
  // Solves the class's part of L q = rhs into q; returns the V-cycles used. Throws
  // Status::failure when 200 cycles do not reach the tolerance.
  int solve(const Layout& layout, const Field& rhs, Field& q) const;

  struct Level;

 private:
  std::array<std::vector<int>, 3> nodes_;
  std::vector<double> weight_;
  std::vector<std::unique_ptr<Level>> levels_;
  std::vector<double> coarse_pinv_;
  double tol_;
};

}  // namespace fest::fluidsim
