#include "fluidsim/spectral.hpp"

#include <cmath>
#include <cstdlib>
#include <mutex>

#include <Eigen/Dense>
#include <fftw3.h>

#include "core/error.hpp"

namespace fest::fluidsim {

namespace {

// FFTW's planner is not thread-safe; plans are made once per basis under this lock and
// executed concurrently afterwards with fftw_execute_r2r (new-array execution).
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace

// Which real-to-real transform diagonalizes the 1-D operator, from its end conditions:
// whole-sample mirror (a wall node ends the set) or half-sample mirror (the node next to
// the wall), wrap-around, or Dirichlet zeros beyond the ends.
struct AxisBasis::Fft {
  enum class Kind { identity, dct1, dct2, whole_half, half_whole, dst1, periodic } kind;
  int m = 0;        // nodes
  int length = 0;   // transform length
  double scale = 1; // inverse normalisation
  fftw_plan fwd = nullptr, inv = nullptr;
  ~Fft() {
    std::lock_guard<std::mutex> lock(planner_mutex());
    if (fwd) fftw_destroy_plan(fwd);
    if (inv) fftw_destroy_plan(inv);
  }
};

AxisBasis::AxisBasis(const Layout& L, int axis, std::vector<int> nodes, int reach, Parity parity,
                     Transform kind)
    : nodes_(std::move(nodes)) {
  const int m = size();
  const double c = 1.0 / ((reach * L.h) * (reach * L.h));
  std::vector<int> position(L.size[axis], -1);
  // Node lists are in stencil order: increasing, or a stride-2 walk around an odd cycle.
  for (int p = 0; p < m; ++p) position[nodes_[p]] = p;

  // The operator, assembled from the stencil and the fold rules, so that every end
  // condition follows from the grid's mirror rules rather than from a case list.
  matrix_.assign(static_cast<std::size_t>(m) * m, 0.0);
  for (int p = 0; p < m; ++p) {
    const int g = nodes_[p];
    for (int d : {reach, -reach}) {
      bool flipped = false;
      const int gn = L.fold(axis, g + d, flipped);
      if (parity == Parity::odd && L.is_wall(axis, gn)) continue;  // the wall value is 0
      const double sign = (parity == Parity::odd && flipped) ? -1.0 : 1.0;
      if (position[gn] < 0) throw runtime_failure("internal: stencil leaves its parity class");
      matrix_[static_cast<std::size_t>(p) * m + position[gn]] += c * sign;
    }
    matrix_[static_cast<std::size_t>(p) * m + p] -= 2.0 * c;
  }

  // Trapezoid weights make T symmetric: S = W^1/2 T W^-1/2.
  Eigen::VectorXd w(m);
  for (int p = 0; p < m; ++p)
    w[p] = (parity == Parity::even && L.is_wall(axis, nodes_[p])) ? 0.5 : 1.0;
  Eigen::MatrixXd S(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      S(i, j) = std::sqrt(w[i]) * matrix_[static_cast<std::size_t>(i) * m + j] / std::sqrt(w[j]);
  S = 0.5 * (S + S.transpose()).eval();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(S);
  const Eigen::VectorXd& lam = eig.eigenvalues();
  const Eigen::MatrixXd& U = eig.eigenvectors();
  const double lmax = lam.cwiseAbs().maxCoeff();
  lambda_.resize(m);
  fwd_.resize(static_cast<std::size_t>(m) * m);
  inv_.resize(static_cast<std::size_t>(m) * m);
  for (int k = 0; k < m; ++k) {
    lambda_[k] = std::fabs(lam[k]) <= 1e-11 * std::max(lmax, 1e-300) ? 0.0 : lam[k];
    for (int j = 0; j < m; ++j) {
      fwd_[static_cast<std::size_t>(k) * m + j] = U(j, k) * std::sqrt(w[j]);
      inv_[static_cast<std::size_t>(j) * m + k] = U(j, k) / std::sqrt(w[j]);
    }
  }
  if (kind == Transform::dense || m < 2) return;

  // FFTW path: choose the transform from the end conditions.
  auto f = std::make_unique<Fft>();
  f->m = m;
  const bool periodic = L.bc[axis] == Boundary::periodic;
  using K = Fft::Kind;
  if (periodic) {
    f->kind = K::periodic;
    f->length = m;
    f->scale = 1.0 / m;
  } else if (parity == Parity::odd) {
    if (nodes_.front() != 1 || nodes_.back() != L.size[axis] - 2 || reach != 1) return;  // dense
    f->kind = K::dst1;
    f->length = m;
    f->scale = 1.0 / (2.0 * (m + 1));
  } else {
    const bool left_whole = nodes_.front() == 0, right_whole = nodes_.back() == L.size[axis] - 1;
    if (left_whole && right_whole) {
      f->kind = K::dct1;
      f->length = m;
      f->scale = 1.0 / (2.0 * (m - 1));
    } else if (!left_whole && !right_whole) {
      f->kind = K::dct2;
      f->length = m;
      f->scale = 1.0 / (2.0 * m);
    } else {
      // Whole-sample at one end, half-sample at the other: the mirror images repeat with
      // the odd period 2m-1, an even sequence whose real DFT is the transform (DCT-V).
      f->kind = left_whole ? K::whole_half : K::half_whole;
      f->length = 2 * m - 1;
      f->scale = 1.0 / (2 * m - 1);
    }
  }
  // Eigenvalues of the transform's modes, in its output order.
  const int node_step = m > 1 ? nodes_[1] - nodes_[0] : 1;
  const int shift = reach / node_step;  // stencil reach in positions of the set
  for (int k = 0; k < m; ++k) {
    double theta = 0.0;
    switch (f->kind) {
      case K::dct1: theta = M_PI * k / (m - 1); break;
      case K::dct2: theta = M_PI * k / m; break;
      case K::whole_half:
      case K::half_whole: theta = 2.0 * M_PI * k / (2 * m - 1); break;
      case K::dst1: theta = M_PI * (k + 1) / (m + 1); break;
      case K::periodic: {
        const int freq = k <= m / 2 ? k : m - k;
        theta = 2.0 * M_PI * shift * freq / m;
        break;
      }
      case K::identity: break;
    }
    const double s = std::sin(0.5 * theta);
    lambda_[k] = -4.0 * c * s * s;
    if (std::fabs(lambda_[k]) <= 1e-13 * c) lambda_[k] = 0.0;
  }
  std::lock_guard<std::mutex> lock(planner_mutex());
  std::vector<double> a(f->length + 2), b(f->length + 2);
  const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
  fftw_r2r_kind kf = FFTW_R2HC, ki = FFTW_HC2R;
  switch (f->kind) {
    case K::dct1: kf = ki = FFTW_REDFT00; break;
    case K::dct2: kf = FFTW_REDFT10; ki = FFTW_REDFT01; break;
    case K::dst1: kf = ki = FFTW_RODFT00; break;
    default: break;
  }
  f->fwd = fftw_plan_r2r_1d(f->length, a.data(), b.data(), kf, flags);
  f->inv = fftw_plan_r2r_1d(f->length, a.data(), b.data(), ki, flags);
  if (!f->fwd || !f->inv) throw runtime_failure("FFTW could not plan a transform of length {}", f->length);
  fft_ = std::move(f);
}

AxisBasis::~AxisBasis() = default;

// The work line holds the transform's input, then (from length + 1) its output. Node j of
// the set in the transform's order: half_whole runs the set backwards; the whole/half
// kinds see the set mirrored into the odd period 2m - 1 (DCT-V as a real DFT).
void AxisBasis::forward(double* line, std::ptrdiff_t stride, double* work) const {
  const Fft& f = *fft_;
  const int m = f.m;
  double* in = work;
  double* out = work + f.length + 1;
  const bool mirrored = f.kind == Fft::Kind::whole_half || f.kind == Fft::Kind::half_whole;
  for (int j = 0; j < m; ++j) {
    const double v = line[(f.kind == Fft::Kind::half_whole ? m - 1 - j : j) * stride];
    in[j] = v;
    if (mirrored && j > 0) in[f.length - j] = v;
  }
  fftw_execute_r2r(f.fwd, in, out);
  for (int k = 0; k < m; ++k) line[k * stride] = out[k];
}

void AxisBasis::inverse(double* line, std::ptrdiff_t stride, double* work) const {
  const Fft& f = *fft_;
  const int m = f.m;
  // Modes past m (the mirrored half of the period) are zero.
  const int filled = f.kind == Fft::Kind::whole_half || f.kind == Fft::Kind::half_whole ? f.length : m;
  for (int k = 0; k < filled; ++k) work[k] = k < m ? line[k * stride] : 0.0;
  double* out = work + f.length + 1;
  fftw_execute_r2r(f.inv, work, out);
  for (int j = 0; j < m; ++j) line[(f.kind == Fft::Kind::half_whole ? m - 1 - j : j) * stride] = out[j] * f.scale;
}

BoxSolver::BoxSolver(std::array<std::shared_ptr<const AxisBasis>, 3> axes, double a, double b)
    : axes_(std::move(axes)) {
  const int m0 = axes_[0]->size(), m1 = axes_[1]->size(), m2 = axes_[2]->size();
  count_ = static_cast<std::size_t>(m0) * m1 * m2;
  inv_factor_.resize(count_);
  const auto& l0 = axes_[0]->eigenvalues();
  const auto& l1 = axes_[1]->eigenvalues();
  const auto& l2 = axes_[2]->eigenvalues();
  std::size_t n = 0;
  for (int k = 0; k < m2; ++k)
    for (int j = 0; j < m1; ++j)
      for (int i = 0; i < m0; ++i, ++n) {
        const double sum = l0[i] + l1[j] + l2[k];
        // The null space (all axes in their constant/zero mode) of a pure Poisson problem.
        const double factor = (a == 0.0 && sum == 0.0) ? 0.0 : a + b * sum;
        inv_factor_[n] = factor == 0.0 ? 0.0 : 1.0 / factor;
      }

  // A dense z axis whose operator is tridiagonal (closed; a periodic axis wraps) is solved
  // directly by elimination in x/y eigen space instead of with two dense transforms: a
  // third of the transform work. The system -(b T_z + shift) with shift <= 0 is a
  // diagonally dominant M-matrix for the Poisson and diffusion operators (b T_z has the
  // sign of b, every x/y eigenvalue lambda <= 0), so elimination without pivoting is
  // stable. Lines whose shift is 0 (the null mode of a pure Poisson problem) are singular
  // and keep the eigen-space solve, which zeroes the null mode.
  const AxisBasis& z = *axes_[2];
  bool banded = m2 >= 2 && !z.uses_fftw();
  const std::vector<double>& T = z.matrix();
  for (int r = 0; banded && r < m2; ++r)
    for (int col = 0; col < m2; ++col)
      if (std::abs(r - col) > 1 && T[static_cast<std::size_t>(r) * m2 + col] != 0.0) banded = false;
  if (!banded) return;
  tridiagonal_z_ = true;
  sub_.assign(m2, 0.0);
  diag_.assign(m2, 0.0);
  super_.assign(m2, 0.0);
  for (int r = 0; r < m2; ++r) {
    const std::size_t row = static_cast<std::size_t>(r) * m2;
    diag_[r] = b * T[row + r];
    if (r > 0) sub_[r] = b * T[row + r - 1];
    if (r + 1 < m2) super_[r] = b * T[row + r + 1];
  }
  shift_.resize(static_cast<std::size_t>(m0) * m1);
  for (int j = 0; j < m1; ++j)
    for (int i = 0; i < m0; ++i) {
      const double sum = l0[i] + l1[j];
      const double s = (a == 0.0 && sum == 0.0) ? 0.0 : a + b * sum;
      shift_[i + static_cast<std::size_t>(m0) * j] = s;
      if (s == 0.0) null_lines_.push_back(i + m0 * j);
    }
}

void BoxSolver::solve_z_tridiagonal(double* X, double* cp) const {
  const int m2 = axes_[2]->size();
  const std::size_t P = shift_.size();  // lines, one per x/y mode; plane k holds X[k P + p]
  // Singular lines first, in eigen space (their elimination would divide by ~0).
  std::vector<double> line(m2), coef(m2);
  const std::vector<double>& F = axes_[2]->forward_matrix();
  const std::vector<double>& B = axes_[2]->inverse_matrix();
  std::vector<std::vector<double>> singular;
  for (int p : null_lines_) {
    for (int k = 0; k < m2; ++k) line[k] = X[k * P + p];
    for (int k = 0; k < m2; ++k) {
      double s = 0.0;
      for (int j = 0; j < m2; ++j) s += F[static_cast<std::size_t>(k) * m2 + j] * line[j];
      coef[k] = s * inv_factor_[k * P + p];
    }
    for (int j = 0; j < m2; ++j) {
      double s = 0.0;
      for (int k = 0; k < m2; ++k) s += B[static_cast<std::size_t>(j) * m2 + k] * coef[k];
      line[j] = s;
    }
    singular.push_back(line);
  }
  // Elimination (Thomas), every line at once: plane by plane, the inner loop runs over
  // the contiguous x/y modes. cp holds the eliminated super-diagonal.
  const double* sh = shift_.data();
  for (std::size_t p = 0; p < P; ++p) {
    const double inv = 1.0 / (diag_[0] + sh[p]);
    cp[p] = super_[0] * inv;
    X[p] *= inv;
  }
  for (int k = 1; k < m2; ++k) {
    const double a = sub_[k], d = diag_[k], c = super_[k];
    const double* cprev = cp + (k - 1) * P;
    const double* xprev = X + (k - 1) * P;
    double* ck = cp + k * P;
    double* xk = X + k * P;
    for (std::size_t p = 0; p < P; ++p) {
      const double inv = 1.0 / (d + sh[p] - a * cprev[p]);
      ck[p] = c * inv;
      xk[p] = (xk[p] - a * xprev[p]) * inv;
    }
  }
  for (int k = m2 - 2; k >= 0; --k) {
    const double* ck = cp + k * P;
    const double* xnext = X + (k + 1) * P;
    double* xk = X + k * P;
    for (std::size_t p = 0; p < P; ++p) xk[p] -= ck[p] * xnext[p];
  }
  for (std::size_t l = 0; l < null_lines_.size(); ++l)
    for (int k = 0; k < m2; ++k) X[k * P + null_lines_[l]] = singular[l][k];
}

namespace {

// Applies a dense m x m matrix (row-major) along one axis of a box array (x fastest),
// from X into Y (the product is written in place of Y, no temporary), then swaps them.
void dense_along(const std::vector<double>& M, int axis, const int dims[3], std::vector<double>& X,
                 std::vector<double>& Y) {
  const int m = dims[axis];
  Eigen::Map<const RowMatrix> A(M.data(), m, m);
  if (axis == 0) {
    Eigen::Map<const Eigen::MatrixXd> B(X.data(), dims[0], dims[1] * dims[2]);
    Eigen::Map<Eigen::MatrixXd> C(Y.data(), dims[0], dims[1] * dims[2]);
    C.noalias() = A * B;
  } else if (axis == 2) {
    Eigen::Map<const Eigen::MatrixXd> B(X.data(), dims[0] * dims[1], dims[2]);
    Eigen::Map<Eigen::MatrixXd> C(Y.data(), dims[0] * dims[1], dims[2]);
    C.noalias() = B * A.transpose();
  } else {
    for (int k = 0; k < dims[2]; ++k) {
      const std::size_t slab = static_cast<std::size_t>(k) * dims[0] * dims[1];
      Eigen::Map<const Eigen::MatrixXd> B(X.data() + slab, dims[0], dims[1]);
      Eigen::Map<Eigen::MatrixXd> C(Y.data() + slab, dims[0], dims[1]);
      C.noalias() = B * A.transpose();
    }
  }
  X.swap(Y);
}

void fft_along(const AxisBasis& basis, bool forward, int axis, const int dims[3], std::vector<double>& X,
               std::vector<double>& work) {
  const std::ptrdiff_t stride = axis == 0 ? 1 : axis == 1 ? dims[0] : static_cast<std::ptrdiff_t>(dims[0]) * dims[1];
  const int o1 = axis == 0 ? 1 : 0, o2 = axis == 2 ? 1 : 2;
  const std::ptrdiff_t s1 = o1 == 0 ? 1 : dims[0];
  const std::ptrdiff_t s2 = o2 == 1 ? dims[0] : static_cast<std::ptrdiff_t>(dims[0]) * dims[1];
  for (int b = 0; b < dims[o2]; ++b)
    for (int a = 0; a < dims[o1]; ++a) {
      double* line = X.data() + a * s1 + b * s2;
      if (forward)
        basis.forward(line, stride, work.data());
      else
        basis.inverse(line, stride, work.data());
    }
}

}  // namespace

void BoxSolver::solve(const Layout& L, const Field& rhs, Field& x) const {
  const int dims[3] = {axes_[0]->size(), axes_[1]->size(), axes_[2]->size()};
  const auto& n0 = axes_[0]->nodes();
  const auto& n1 = axes_[1]->nodes();
  const auto& n2 = axes_[2]->nodes();
  std::vector<double> X(count_), Y(count_);  // Y: the other half of a ping-pong pair
  std::size_t n = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) X[n++] = rhs[L.index(n0[i], n1[j], n2[k])];

  int longest = 1;
  for (int a = 0; a < 3; ++a) longest = std::max(longest, 2 * dims[a] + 2);
  std::vector<double> work(2 * longest + 4);
  const int transformed = tridiagonal_z_ ? 2 : 3;  // axes in eigen space
  for (int a = 0; a < transformed; ++a) {
    if (dims[a] == 1) {
      continue;  // a 1-node axis: its transform is the identity (eigenvalue 0 or its own)
    }
    if (axes_[a]->uses_fftw())
      fft_along(*axes_[a], true, a, dims, X, work);
    else
      dense_along(axes_[a]->forward_matrix(), a, dims, X, Y);
  }
  if (tridiagonal_z_) {
    solve_z_tridiagonal(X.data(), Y.data());
  } else {
    for (std::size_t i = 0; i < count_; ++i) X[i] *= inv_factor_[i];
  }
  for (int a = transformed - 1; a >= 0; --a) {
    if (dims[a] == 1) continue;
    if (axes_[a]->uses_fftw())
      fft_along(*axes_[a], false, a, dims, X, work);
    else
      dense_along(axes_[a]->inverse_matrix(), a, dims, X, Y);
  }
  n = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) x[L.index(n0[i], n1[j], n2[k])] = X[n++];
}

}  // namespace fest::fluidsim
