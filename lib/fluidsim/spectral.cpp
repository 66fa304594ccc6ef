#include "fluidsim/spectral.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>

#include <Eigen/Dense>
#include <fftw3.h>

#include "core/error.hpp"
#include "fluidsim/dense_product.hpp"

namespace fest::fluidsim {

namespace {

// FFTW's planner is not thread-safe; plans are made once per basis under this lock and
// executed concurrently afterwards with fftw_execute_r2r (new-array execution).
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

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
  if (!axes_[0]->uses_fftw()) {
    x_forward_ = pack_rows(axes_[0]->forward_matrix().data(), m0, 1, m0, m0);
    x_inverse_ = pack_rows(axes_[0]->inverse_matrix().data(), m0, 1, m0, m0);
  }

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

namespace {

// Boxes with fewer nodes in all, or of grids below kParallelNodes, are solved on one thread
// (the 8 classes of a 32^3 grid hold 39,304): below that a parallel region costs more than
// the work.
constexpr std::size_t kParallelBox = 4096;
// The parallel units are pieces of a box: rows or columns of a dense product, lines of a
// transform, x/y modes of the elimination, rows of the gather and scatter. Every node's
// arithmetic is the same in any piece, so results do not depend on how the pieces are
// cut or shared out (docs/fluidsim.md §6). The size follows from the work alone (not from
// the thread count): 8 to 64 units, a multiple of 8 (a register block of the product),
// about 256 pieces where there is enough work, so that 16 threads balance.
int piece_size(std::size_t units) {
  const std::size_t s = units / 256 / 8 * 8;
  return static_cast<int>(std::min<std::size_t>(64, std::max<std::size_t>(8, s)));
}
int pieces(std::size_t n, int piece) { return static_cast<int>((n + piece - 1) / piece); }
constexpr int kValues = 1024;  // values per piece of the eigen-space division

// Lines of an FFTW transform along `axis`: `across` of them side by side (x for y and z
// lines, y for x lines) at `across_step`, repeated `outer` times at `outer_step`.
struct Lines {
  int across, outer;
  std::ptrdiff_t stride, across_step, outer_step;
  Lines(int axis, const int dims[3]) {
    stride = axis == 0 ? 1 : axis == 1 ? dims[0] : static_cast<std::ptrdiff_t>(dims[0]) * dims[1];
    across = axis == 0 ? dims[1] : dims[0];
    outer = axis == 2 ? dims[1] : dims[2];
    across_step = axis == 0 ? dims[0] : 1;
    outer_step = axis == 2 ? dims[0] : static_cast<std::ptrdiff_t>(dims[0]) * dims[1];
  }
  int size() const { return piece_size(static_cast<std::size_t>(across) * outer); }
  int per_outer() const { return pieces(static_cast<std::size_t>(across), size()); }
  int count() const { return outer * per_outer(); }
};

int dense_pieces(int axis, const int dims[3]) {
  if (axis == 0) {
    const std::size_t columns = static_cast<std::size_t>(dims[1]) * dims[2];
    return pieces(columns, piece_size(columns));
  }
  if (axis == 1) return dims[2] * pieces(dims[0], piece_size(static_cast<std::size_t>(dims[0]) * dims[2]));
  const std::size_t plane = static_cast<std::size_t>(dims[0]) * dims[1];
  return pieces(plane, piece_size(plane));
}

// One piece of a dense m x m matrix M (row-major; `packed`: its rows packed, for x) applied
// along one axis of a box array (x fastest) from X into Y. Pieces: columns (x lines) for
// x, (plane, x rows) for y, x/y rows for z.
void dense_piece(const std::vector<double>& M, const std::vector<double>& packed, int axis, const int dims[3],
                 const double* X, double* Y, int piece) {
  const int m = dims[axis];
  const std::ptrdiff_t plane = static_cast<std::ptrdiff_t>(dims[0]) * dims[1];
  if (axis == 0) {
    // Y(i, c) = sum_j M(i, j) X(j, c) over the columns c (x lines) of the box.
    const std::size_t columns = static_cast<std::size_t>(dims[1]) * dims[2];
    const int size = piece_size(columns);
    const std::size_t c0 = static_cast<std::size_t>(piece) * size;
    const int n = static_cast<int>(std::min<std::size_t>(size, columns - c0));
    dense_product_packed(packed.data(), m, X + c0 * m, m, 1, Y + c0 * m, m, n, m);
  } else if (axis == 1) {
    // Per plane k: Y_k(i, r) = sum_j X_k(i, j) M(r, j), in pieces of x rows.
    const int size = piece_size(static_cast<std::size_t>(dims[0]) * dims[2]);
    const int per_plane = pieces(dims[0], size);
    const int k = piece / per_plane, i0 = (piece % per_plane) * size;
    const std::ptrdiff_t at = k * plane + i0;
    dense_product(X + at, 1, dims[0], M.data(), m, 1, Y + at, dims[0], std::min(size, dims[0] - i0), m, m);
  } else {
    // Y(p, r) = sum_j X(p, j) M(r, j) over the x/y rows p.
    const int size = piece_size(static_cast<std::size_t>(plane));
    const std::ptrdiff_t p0 = static_cast<std::ptrdiff_t>(piece) * size;
    const int n = static_cast<int>(std::min<std::ptrdiff_t>(size, plane - p0));
    dense_product(X + p0, 1, plane, M.data(), m, 1, Y + p0, plane, n, m, m);
  }
}

}  // namespace

// Per-thread buffers of the FFTW lines: the transform's work line and a block of 8
// gathered lines.
struct BoxSolver::Scratch {
  std::vector<double> work, block;
  explicit Scratch(int longest) : work(2 * (2 * longest + 2) + 4), block(static_cast<std::size_t>(8) * longest) {}
};

namespace {

// One piece of FFTW transforms along one axis, line by line (each line its own 1-D
// transform). Lines along y and z are strided; 8 neighbours along x are gathered together
// (8 contiguous values, one cache line, per step) into a contiguous block, transformed
// there and scattered back. Pieces: runs of lines along x (within a plane or row of lines).
void fft_piece(const AxisBasis& basis, bool forward, int axis, const int dims[3], double* X, int piece,
               BoxSolver::Scratch& scratch) {
  const int m = dims[axis];
  const Lines lines(axis, dims);
  const int size = lines.size(), per_outer = lines.per_outer();
  const int o = piece / per_outer, a0 = (piece % per_outer) * size;
  const int a1 = std::min(lines.across, a0 + size);
  double* row = X + o * lines.outer_step;
  double* work = scratch.work.data();
  auto transform = [&](double* line) {
    if (forward)
      basis.forward(line, 1, work);
    else
      basis.inverse(line, 1, work);
  };
  if (axis == 0) {
    for (int a = a0; a < a1; ++a) transform(row + a * lines.across_step);
    return;
  }
  constexpr int kBatch = 8;
  double* block = scratch.block.data();
  for (int b0 = a0; b0 < a1; b0 += kBatch) {
    const int nb = std::min(kBatch, a1 - b0);
    double* first = row + b0;
    for (int j = 0; j < m; ++j)
      for (int l = 0; l < nb; ++l) block[static_cast<std::size_t>(l) * m + j] = first[j * lines.stride + l];
    for (int l = 0; l < nb; ++l) transform(block + static_cast<std::size_t>(l) * m);
    for (int j = 0; j < m; ++j)
      for (int l = 0; l < nb; ++l) first[j * lines.stride + l] = block[static_cast<std::size_t>(l) * m + j];
  }
}

}  // namespace

bool BoxSolver::transformed(int axis) const noexcept {
  return dim(axis) > 1 && (axis < 2 || !tridiagonal_z_);  // a 1-node axis's transform is the identity
}

// Stages: 0 gather, 1-3 forward x y z, 4 divide (or eliminate along z), 5-7 inverse z y x,
// 8 scatter.
int BoxSolver::stage_pieces(int stage) const {
  const int dims[3] = {dim(0), dim(1), dim(2)};
  if (stage == 0 || stage == 8) return dims[1] * dims[2];  // rows
  if (stage == 4)
    return tridiagonal_z_ ? pieces(shift_.size(), piece_size(shift_.size())) : pieces(count_, kValues);
  const int axis = stage < 4 ? stage - 1 : 7 - stage;
  if (!transformed(axis)) return 0;
  return axes_[axis]->uses_fftw() ? Lines(axis, dims).count() : dense_pieces(axis, dims);
}

bool BoxSolver::stage_swaps(int stage) const {
  if (stage == 0 || stage == 4 || stage == 8) return false;
  const int axis = stage < 4 ? stage - 1 : 7 - stage;
  return transformed(axis) && !axes_[axis]->uses_fftw();
}

void BoxSolver::stage_piece(int stage, int piece, const Layout& L, const Field& rhs, Field& x, double* X, double* Y,
                            Scratch& scratch) const {
  const int dims[3] = {dim(0), dim(1), dim(2)};
  if (stage == 0 || stage == 8) {
    const auto& n0 = axes_[0]->nodes();
    const int j = piece % dims[1], k = piece / dims[1];
    const int nj = axes_[1]->nodes()[j], nk = axes_[2]->nodes()[k];
    double* o = X + static_cast<std::size_t>(piece) * dims[0];
    if (stage == 0)
      for (int i = 0; i < dims[0]; ++i) o[i] = rhs[L.index(n0[i], nj, nk)];
    else
      for (int i = 0; i < dims[0]; ++i) x[L.index(n0[i], nj, nk)] = o[i];
    return;
  }
  if (stage == 4) {
    if (tridiagonal_z_) {
      const std::size_t P = shift_.size();
      const std::size_t size = piece_size(P);
      const std::size_t p0 = piece * size;
      eliminate_z(X, Y, p0, std::min(P, p0 + size));
    } else {
      const std::size_t i0 = static_cast<std::size_t>(piece) * kValues;
      const std::size_t i1 = std::min(count_, i0 + kValues);
      const double* f = inv_factor_.data();
      for (std::size_t i = i0; i < i1; ++i) X[i] *= f[i];
    }
    return;
  }
  const bool forward = stage < 4;
  const int axis = forward ? stage - 1 : 7 - stage;
  const AxisBasis& basis = *axes_[axis];
  if (basis.uses_fftw())
    fft_piece(basis, forward, axis, dims, X, piece, scratch);
  else
    dense_piece(forward ? basis.forward_matrix() : basis.inverse_matrix(), forward ? x_forward_ : x_inverse_, axis,
                dims, X, Y, piece);
}

void BoxSolver::eliminate_z(double* X, double* cp, std::size_t p0, std::size_t p1) const {
  const int m2 = dim(2);
  const std::size_t P = shift_.size();  // lines, one per x/y mode; plane k holds X[k P + p]
  // Singular lines of this piece first, in eigen space (their elimination would divide by
  // ~0); their solution replaces the eliminated one at the end.
  std::vector<std::pair<int, std::vector<double>>> singular;
  const std::vector<double>& F = axes_[2]->forward_matrix();
  const std::vector<double>& B = axes_[2]->inverse_matrix();
  for (int p : null_lines_) {
    if (static_cast<std::size_t>(p) < p0 || static_cast<std::size_t>(p) >= p1) continue;
    std::vector<double> line(m2), coef(m2);
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
    singular.emplace_back(p, std::move(line));
  }
  // Elimination (Thomas) of the piece's lines at once, plane by plane, the inner loop over
  // contiguous x/y modes (vectorised; a piece's planes stay in cache). cp holds the
  // eliminated super-diagonal.
  const double* sh = shift_.data();
  for (std::size_t p = p0; p < p1; ++p) {
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
    for (std::size_t p = p0; p < p1; ++p) {
      const double inv = 1.0 / (d + sh[p] - a * cprev[p]);
      ck[p] = c * inv;
      xk[p] = (xk[p] - a * xprev[p]) * inv;
    }
  }
  for (int k = m2 - 2; k >= 0; --k) {
    const double* ck = cp + k * P;
    const double* xnext = X + (k + 1) * P;
    double* xk = X + k * P;
    for (std::size_t p = p0; p < p1; ++p) xk[p] -= ck[p] * xnext[p];
  }
  for (const auto& [p, line] : singular)
    for (int k = 0; k < m2; ++k) X[k * P + p] = line[k];
}

void BoxSolver::solve(const Layout& L, const Field& rhs, Field& x, BoxBuffers* buffers) const {
  solve_all(L, {BoxJob{this, &rhs, &x}}, buffers);
}

void BoxSolver::solve_all(const Layout& L, const std::vector<BoxJob>& jobs, BoxBuffers* buffers) {
  const std::size_t nb = jobs.size();
  if (nb == 0) return;
  // Each box's ping-pong pair; every value is written before it is read (no zero fill;
  // the first touch of fresh buffers happens in the parallel gather).
  BoxBuffers local;
  BoxBuffers& store = buffers ? *buffers : local;
  if (store.data.size() < 2 * nb) {
    store.data.resize(2 * nb);
    store.size.resize(2 * nb, 0);
  }
  std::size_t total = 0;
  int longest = 1;
  for (std::size_t b = 0; b < nb; ++b) {
    const BoxSolver& s = *jobs[b].solver;
    for (std::size_t k = 2 * b; k < 2 * b + 2; ++k)
      if (store.size[k] < s.count_) {
        store.data[k].reset(new double[s.count_]);
        store.size[k] = s.count_;
      }
    total += s.count_;
    for (int a = 0; a < 3; ++a) longest = std::max(longest, s.dim(a));
  }
  // Where each box's pieces start in each stage's loop.
  std::array<std::vector<int>, kStages> first;
  for (int st = 0; st < kStages; ++st) {
    first[st].assign(nb + 1, 0);
    for (std::size_t b = 0; b < nb; ++b) first[st][b + 1] = first[st][b] + jobs[b].solver->stage_pieces(st);
  }
  const bool parallel = L.count() >= kParallelNodes && total >= kParallelBox;
#pragma omp parallel if (parallel)
  {
    Scratch scratch(longest);
    // Every thread keeps its own view of the pairs and swaps it the same way.
    std::vector<double*> X(nb), Y(nb);
    for (std::size_t b = 0; b < nb; ++b) {
      X[b] = store.data[2 * b].get();
      Y[b] = store.data[2 * b + 1].get();
    }
    for (int st = 0; st < kStages; ++st) {
      const std::vector<int>& f = first[st];
      if (f[nb] == 0) continue;  // the same on every thread
      // Round robin: the boxes' pieces differ in cost (a DST of 64 nodes next to a DCT of
      // 66), and contiguous shares would give one thread the costly ones.
#pragma omp for schedule(static, 1)
      for (int t = 0; t < f[nb]; ++t) {
        const std::size_t b = static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), t) - f.begin()) - 1;
        jobs[b].solver->stage_piece(st, t - f[b], L, *jobs[b].rhs, *jobs[b].x, X[b], Y[b], scratch);
      }
      for (std::size_t b = 0; b < nb; ++b)
        if (jobs[b].solver->stage_swaps(st)) std::swap(X[b], Y[b]);
    }
  }
}

}  // namespace fest::fluidsim
