#pragma once
// The projection step (docs/fluidsim.md §4): solve L q = D w, then w -= G q.
//
// With the paper's operators (central D and G) L = D G is the wide Laplacian, which
// couples a node only with nodes two apart: the grid splits into 2^d parity classes, each
// an independent Poisson problem, solved concurrently (the chapter's 8-way parallel
// projection). `stam03` replaces L by the compact Laplacian, as Stam's 2003 code does;
// that pair is not an exact projection.

#include <memory>
#include <string>
#include <vector>

#include "fluidsim/grid.hpp"
#include "fluidsim/spectral.hpp"

namespace fest::fluidsim {

enum class PoissonSolver { fdm, fft, mg, gs, jacobi };

// "fdm", "fft", "mg", "gs", "jacobi": the solver's name in reports.
const char* poisson_name(PoissonSolver s) noexcept;

struct ProjectionOptions {
  PoissonSolver solver = PoissonSolver::fdm;
  bool compact = false;  // stam03: compact Laplacian instead of the wide D G
  int iters = 20;        // gs / jacobi sweeps
  double tol = 1e-8;     // mg: relative residual
};

struct ProjectionStats {
  double max_div_before = 0.0;  // max |D w3|
  double max_div_after = 0.0;   // max |D w4|
  int iterations = 0;           // V-cycles or sweeps (0 for direct solvers)
};

// The stored nodes of one axis that form parity class `parity` for a stencil of reach r
// (r = 2: every other node; r = 1 or an odd periodic axis: all nodes).
std::vector<int> class_nodes(const Layout& layout, int axis, int parity, int reach);
// How many classes an axis splits into (2 for reach 2 unless periodic with odd n).
int classes_along(const Layout& layout, int axis, int reach);

// The seed's size rule ("the largest prime factor of dimension + 1"), as it comes out for
// the FFTW transforms of a closed axis: odd n gives a DCT-I over (n+1)/2 intervals and a
// DCT-II of (n+1)/2 nodes, even n two odd-period real DFTs of length n+1; all are fast
// when n+1 has no prime factor above 7.
bool fft_friendly(int n) noexcept;
// The closest n (smaller one on ties) that is fft_friendly.
int nearest_fft_friendly(int n) noexcept;

class MultigridClass;

class Projector {
 public:
  Projector(const Layout& layout, const ProjectionOptions& options);
  ~Projector();
  Projector(const Projector&) = delete;
  Projector& operator=(const Projector&) = delete;

  // Projects u in place; wall-normal components end at 0.
  ProjectionStats project(Velocity& u) const;
  // Solves L q = rhs (class by class for the direct and multigrid solvers); q is
  // overwritten. Returns the iteration count of iterative solvers.
  int solve(const Field& rhs, Field& q) const;
  // Applies L with the mirror rules (even q).
  void apply_laplacian(const Field& q, Field& out) const;

  int class_count() const noexcept { return static_cast<int>(classes_.size()); }
  // Sizes (nodes per axis) of class c.
  std::array<int, 3> class_size(int c) const;
  const ProjectionOptions& options() const noexcept { return options_; }

 private:
  int iterate(const Field& rhs, Field& q) const;

  Layout layout_;
  ProjectionOptions options_;
  int reach_ = 2;
  std::vector<std::unique_ptr<BoxSolver>> classes_;
  mutable BoxBuffers buffers_;  // the classes' work arrays, kept between steps
  mutable Field div_, q_;       // project()'s divergence and potential, likewise
  std::vector<std::unique_ptr<MultigridClass>> multigrid_;
  std::array<AxisNeighbours, 3> nb_;
};

}  // namespace fest::fluidsim
