#pragma once
// Fast diagonalization of separable operators (docs/fluidsim.md §4, solvers `fdm` and
// `fft`). An operator on a box of nodes that is a Kronecker sum Tx (+) Ty (+) Tz of 1-D
// operators is diagonalized axis by axis: transform, divide by the eigenvalue sums,
// transform back. Used for the 2^d parity classes of the wide Laplacian (projection) and
// for the compact Laplacian of implicit diffusion.
//
// Each 1-D operator is a second difference of reach r (r = 2: wide, r = 1: compact) on a
// set of stored nodes of one axis, with the grid's mirror/wrap rules and a field parity.
// It is symmetric in the trapezoid-weighted inner product W (1/2 on wall nodes), so
// T = V diag(lambda) V^-1 with V = W^-1/2 U.

#include <memory>
#include <vector>

#include "fluidsim/grid.hpp"

namespace fest::fluidsim {

enum class Transform { dense, fftw };

// One axis: the node set, the eigenvalues and the transform in and out of eigen space.
class AxisBasis {
 public:
  // nodes: stored indices of the axis, increasing, every r-th (a parity class for r = 2,
  // all interior or all stored nodes for r = 1). Odd parity drops wall neighbours (their
  // value is 0).
  AxisBasis(const Layout& layout, int axis, std::vector<int> nodes, int reach, Parity parity,
            Transform kind);
  ~AxisBasis();
  AxisBasis(const AxisBasis&) = delete;
  AxisBasis& operator=(const AxisBasis&) = delete;

  int size() const noexcept { return static_cast<int>(nodes_.size()); }
  const std::vector<int>& nodes() const noexcept { return nodes_; }
  const std::vector<double>& eigenvalues() const noexcept { return lambda_; }
  // The dense 1-D operator (for tests).
  const std::vector<double>& matrix() const noexcept { return matrix_; }
  bool uses_fftw() const noexcept { return fft_ != nullptr; }

  // Transforms `count` lines of this axis in place: line l starts at data + l*dist (given
  // per line by `starts`), elements `stride` apart. `work` holds at least 2*size()+2.
  void forward(double* line, std::ptrdiff_t stride, double* work) const;
  void inverse(double* line, std::ptrdiff_t stride, double* work) const;
  // Dense matrices (row-major, size x size): coefficients = F x, x = B coefficients.
  const std::vector<double>& forward_matrix() const noexcept { return fwd_; }
  const std::vector<double>& inverse_matrix() const noexcept { return inv_; }

  struct Fft;

 private:
  std::vector<int> nodes_;
  std::vector<double> matrix_, fwd_, inv_, lambda_;
  std::unique_ptr<Fft> fft_;
};

class BoxSolver;

// One box of a multi-box solve: the solver, the right-hand side and the solution field.
struct BoxJob {
  const BoxSolver* solver;
  const Field* rhs;
  Field* x;
};

// Buffers solve_all() keeps from call to call for a caller that solves every step (the
// projector, a diffuser): fresh ones cost page faults and unmapping on every call, kernel
// work that measured ~8 % of a 128^3 step on 2 threads and does not parallelise.
struct BoxBuffers {
  std::vector<std::unique_ptr<double[]>> data;
  std::vector<std::size_t> size;
};

// The solve of (a + b * (lambda_x + lambda_y + lambda_z)) x = rhs on the box of nodes
// nodes_x * nodes_y * nodes_z of a field; modes whose factor is 0 (the Neumann/periodic
// null space of a Poisson problem) are set to 0.
class BoxSolver {
 public:
  BoxSolver(std::array<std::shared_ptr<const AxisBasis>, 3> axes, double a, double b);
  // Gathers the box from `rhs`, solves, and scatters the solution into `x` (other nodes
  // untouched). rhs and x may be the same field. Runs its pieces on the OpenMP team
  // (docs/fluidsim.md §6); the result does not depend on the team's size.
  void solve(const Layout& layout, const Field& rhs, Field& x, BoxBuffers* buffers = nullptr) const;
  // Several boxes (the parity classes of the projection, the velocity components of a
  // diffusion step) stage by stage: each stage's pieces of all the boxes are one parallel
  // loop, so the team waits once per stage rather than once per stage and box. Jobs must
  // not write a node another job reads; each job gives the bytes solve() gives.
  // `buffers` (optional) is reused for the boxes' work arrays; one call at a time.
  static void solve_all(const Layout& layout, const std::vector<BoxJob>& jobs, BoxBuffers* buffers = nullptr);
  std::size_t count() const noexcept { return count_; }
  const std::array<std::shared_ptr<const AxisBasis>, 3>& axes() const noexcept { return axes_; }

  struct Scratch;

 private:
  // The stages of a solve (gather, forward x y z, divide or eliminate, inverse z y x,
  // scatter), each cut into pieces of independent work; see solve_all().
  static constexpr int kStages = 9;
  int dim(int axis) const noexcept { return axes_[axis]->size(); }
  bool transformed(int axis) const noexcept;   // the axis goes through eigen space
  int stage_pieces(int stage) const;
  bool stage_swaps(int stage) const;          // a dense transform wrote the other buffer
  void stage_piece(int stage, int piece, const Layout& layout, const Field& rhs, Field& x, double* X, double* Y,
                   Scratch& scratch) const;
  // The z solve without transforms: line (i,j) in x/y eigen space obeys
  // (b T_z + shift_[i + m0 j]) q = r, a tridiagonal system when T_z is (a closed axis);
  // lines [p0, p1).
  void eliminate_z(double* X, double* cp, std::size_t p0, std::size_t p1) const;

  std::array<std::shared_ptr<const AxisBasis>, 3> axes_;
  std::vector<double> inv_factor_;  // 1 / (a + b * lambda sum), 0 for null modes
  std::size_t count_ = 0;
  bool tridiagonal_z_ = false;
  std::vector<double> sub_, diag_, super_;  // b T_z, by row
  std::vector<double> shift_;               // a + b (lambda_x + lambda_y) per x/y mode
  std::vector<int> null_lines_;             // x/y modes with shift 0: singular lines, solved in eigen space
  std::vector<double> x_forward_, x_inverse_;  // a dense x axis's matrices, rows packed for dense_product
};

}  // namespace fest::fluidsim
