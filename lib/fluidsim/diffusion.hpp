#pragma once
// Implicit diffusion (docs/fluidsim.md §2, step 3): (I - c Lap_h) x = b with the
// compact Laplacian and the mirror rules, c = nu dt (or kappa dt), diagonalized axis by
// axis: even fields on all stored nodes (Neumann, DCT-I), odd fields on the interior
// nodes (Dirichlet, DST-I), periodic axes by the real DFT.

#include <array>
#include <memory>

#include "fluidsim/grid.hpp"
#include "fluidsim/spectral.hpp"

namespace fest::fluidsim {

class Diffuser {
 public:
  // coefficient = nu * dt; no_slip makes tangential velocity components odd at walls.
  Diffuser(const Layout& layout, double coefficient, Transform kind, bool no_slip);
  ~Diffuser();
  // One velocity component c (its parity per axis follows the wall rules).
  void velocity(int component, Field& f) const;
  // Every component of u at once (the same bytes as one at a time, fewer waits).
  void velocity(Velocity& u) const;
  // A scalar (even everywhere).
  void scalar(Field& f) const;
  double coefficient() const noexcept { return coefficient_; }

 private:
  Layout layout_;
  double coefficient_;
  std::array<std::unique_ptr<BoxSolver>, 3> velocity_;
  std::unique_ptr<BoxSolver> scalar_;
  mutable BoxBuffers buffers_;  // the solves' work arrays, kept between steps
};

}  // namespace fest::fluidsim
