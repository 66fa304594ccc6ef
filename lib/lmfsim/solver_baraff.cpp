// Baraff's linear-time solver (Baraff 1996; docs/lmfsim.md §3). The KKT matrix
//   H = [[M, J^T], [J, 0]]
// restricted to the primary constraints is the adjacency pattern of a forest whose
// nodes are bodies and constraints. Eliminating children before parents (block LDL^T)
// costs O(n) with blocks of at most 6x6. Auxiliary rows (loops, redundancies) enter
// through the k x k Schur complement K = B^T H_p^-1 B, solved by truncated SVD so that
// redundant or ill-conditioned loops lose rank gracefully instead of failing.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include <Eigen/LU>

#include "lmfsim/solver.hpp"

namespace fest::lmfsim {
namespace {

// Inverse of a block of at most 6x6 by Gauss-Jordan with partial pivoting. Written out
// because Eigen's dynamic-size LU and GEMM dispatch cost more than the arithmetic for
// blocks this small (the solver's time is almost all in these blocks).
void small_inverse(const Blk& D, Blk& out) {
  const int n = static_cast<int>(D.rows());
  double a[6][12];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      a[i][j] = D(i, j);
      a[i][n + j] = i == j ? 1.0 : 0.0;
    }
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
    if (piv != c)
      for (int j = 0; j < 2 * n; ++j) std::swap(a[c][j], a[piv][j]);
    const double inv = 1.0 / a[c][c];
    for (int j = 0; j < 2 * n; ++j) a[c][j] *= inv;
    for (int r = 0; r < n; ++r) {
      if (r == c || a[r][c] == 0) continue;
      const double f = a[r][c];
      for (int j = 0; j < 2 * n; ++j) a[r][j] -= f * a[c][j];
    }
  }
  out.resize(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) out(i, j) = a[i][n + j];
}

struct Node {
  bool chol_ok = false;
  int dim = 0;
  int parent = -1;
  int constraint = -1;  // index into cons for constraint nodes, -1 for bodies
  int body = -1;        // index of the body for body nodes
  // H_ip (dim x dim(parent)) is the constraint's Jacobian block on the body, read in
  // place: J_side->leftCols(dof) for a constraint node, its transpose for a body node.
  const Blk* J = nullptr;
  Blk D, Dinv, L;
};

// D^-1 of a node's block: Cholesky of +D (bodies, SPD) or -D (constraints, negative
// definite) at fixed size, Gauss-Jordan when the block is not definite (degenerate rows).
// Cholesky factor of sign*D (sign +1 for body blocks, which are SPD; -1 for constraint
// blocks, which are negative definite), row-major lower triangle with the diagonal stored
// inverted so that solves multiply; fixed size so that the loops unroll. False when the
// block is not definite (degenerate rows): the caller falls back to a pivoting inverse.
template <int d>
bool cholesky_fixed(Node& n) {
  const double sign = n.constraint < 0 ? 1.0 : -1.0;
  // Factor in place over D's lower triangle (column-major, leading dimension d): a node
  // keeps no separate factor, so long chains stay in cache. D is symmetric, so its strict
  // upper triangle still holds the original values; on failure the lower triangle is
  // restored from it (and the diagonal from a copy) for the pivoting fallback.
  double* c = n.D.data();
  double diag0[d];
  for (int j = 0; j < d; ++j) diag0[j] = c[j + j * d];
  for (int j = 0; j < d; ++j) {
    double diag = sign * c[j + j * d];
    for (int k = 0; k < j; ++k) diag -= c[j + k * d] * c[j + k * d];
    if (!(diag > 0)) {
      for (int jj = 0; jj < d; ++jj) {
        c[jj + jj * d] = diag0[jj];
        for (int i = jj + 1; i < d; ++i) c[i + jj * d] = c[jj + i * d];
      }
      return false;
    }
    const double inv = 1.0 / std::sqrt(diag);
    c[j + j * d] = inv;
    for (int i = j + 1; i < d; ++i) {
      double v = sign * c[i + j * d];
      for (int k = 0; k < j; ++k) v -= c[i + k * d] * c[j + k * d];
      c[i + j * d] = v * inv;
    }
  }
  return true;
}

// x := D^-1 x from the factor of sign*D.
template <int d>
void cholesky_solve_fixed(const Node& n, double* x) {
  const double* c = n.D.data();
  for (int i = 0; i < d; ++i) {
    double v = x[i];
    for (int k = 0; k < i; ++k) v -= c[i + k * d] * x[k];
    x[i] = v * c[i + i * d];
  }
  for (int i = d - 1; i >= 0; --i) {
    double v = x[i];
    for (int k = i + 1; k < d; ++k) v -= c[k + i * d] * x[k];
    x[i] = v * c[i + i * d];
  }
  if (n.constraint >= 0)
    for (int i = 0; i < d; ++i) x[i] = -x[i];
}

template <int d>
void invert_fixed(Node& n) {
  n.chol_ok = cholesky_fixed<d>(n);
  if (!n.chol_ok) small_inverse(n.D, n.Dinv);
}

// Calls f(std::integral_constant<int, k>{}) with k = size (1..5; anything else: 6): block
// sizes become compile-time constants, so Eigen unrolls the fixed-size kernels.
template <typename F>
void with_block_size(int size, const F& f) {
  switch (size) {
    case 1: f(std::integral_constant<int, 1>{}); break;
    case 2: f(std::integral_constant<int, 2>{}); break;
    case 3: f(std::integral_constant<int, 3>{}); break;
    case 4: f(std::integral_constant<int, 4>{}); break;
    case 5: f(std::integral_constant<int, 5>{}); break;
    default: f(std::integral_constant<int, 6>{}); break;
  }
}

void solve_block(const Node& n, double* x) {
  if (!n.chol_ok) {
    double y[6];
    for (int r = 0; r < n.dim; ++r) {
      double v = 0;
      for (int k = 0; k < n.dim; ++k) v += n.Dinv(r, k) * x[k];
      y[r] = v;
    }
    for (int r = 0; r < n.dim; ++r) x[r] = y[r];
    return;
  }
  with_block_size(n.dim, [&](auto d) { cholesky_solve_fixed<decltype(d)::value>(n, x); });
}

void invert_block(Node& n) {
  with_block_size(n.dim, [&](auto d) { invert_fixed<decltype(d)::value>(n); });
}

// Eliminates node n into its parent: L = D^-1 H_ip, D_parent -= H_ip^T L. Fixed-size
// kernels (blocks are at most 6x6; Eigen unrolls and vectorises them).
template <int d, int p, typename HExpr>
void eliminate(Node& n, Blk& Dp, const HExpr& H) {
  using Md = Eigen::Matrix<double, d, d>;
  using Mdp = Eigen::Matrix<double, d, p>;
  using Mp = Eigen::Matrix<double, p, p>;
  n.L.resize(d, p);
  Eigen::Map<Mdp> L(n.L.data());
  if (n.chol_ok) {
    for (int col = 0; col < p; ++col) {
      double x[d];
      for (int r = 0; r < d; ++r) x[r] = H(r, col);
      cholesky_solve_fixed<d>(n, x);
      for (int r = 0; r < d; ++r) L(r, col) = x[r];
    }
  } else {
    L.noalias() = Eigen::Map<const Md>(n.Dinv.data()) * H;
  }
  // D_parent -= H^T L (symmetric: the lower triangle is computed and mirrored).
  Eigen::Map<Mp> P(Dp.data());
  for (int b = 0; b < p; ++b)
    for (int a = b; a < p; ++a) {
      double v = 0;
      for (int r = 0; r < d; ++r) v += H(r, a) * L(r, b);
      P(a, b) -= v;
      if (a != b) P(b, a) -= v;
    }
}

// Factors node n (d x d) into its parent's block Dp (p x p).
struct FactorInto {
  Node& n;
  Blk& Dp;
  template <int d, int p>
  void run() const {
    invert_fixed<d>(n);
    if (n.constraint < 0) {  // body node under a constraint: H = J^T (J is p x 6)
      eliminate<d, p>(n, Dp, Eigen::Map<const Eigen::Matrix<double, p, d>>(n.J->data()).transpose());
    } else {  // constraint node under a body: H = J.leftCols(p) (J is d x 6)
      eliminate<d, p>(n, Dp, Eigen::Map<const Eigen::Matrix<double, d, p>>(n.J->data()));
    }
  }
};

// Calls f.run<d, p>() with the block sizes d, p as compile-time constants (1..6 each).
template <typename F>
void with_sizes(int d, int p, const F& f) {
  with_block_size(d, [&](auto dc) {
    with_block_size(p, [&](auto pc) { f.template run<decltype(dc)::value, decltype(pc)::value>(); });
  });
}

void factor_block(Node& n, Blk& Dp) {
  with_sizes(n.dim, static_cast<int>(Dp.rows()), FactorInto{n, Dp});
}

// Forward sweep of the block solve: x_parent -= L^T x_i.
struct PushUp {
  const Node& n;
  const double* xi;
  double* xp;
  template <int d, int p>
  void run() const {
    Eigen::Map<Eigen::Matrix<double, p, 1>>(xp).noalias() -=
        Eigen::Map<const Eigen::Matrix<double, d, p>>(n.L.data()).transpose() * Eigen::Map<const Eigen::Matrix<double, d, 1>>(xi);
  }
};

// Backward sweep: x_i -= L x_parent.
struct PullDown {
  const Node& n;
  double* xi;
  const double* xp;
  template <int d, int p>
  void run() const {
    Eigen::Map<Eigen::Matrix<double, d, 1>>(xi).noalias() -=
        Eigen::Map<const Eigen::Matrix<double, d, p>>(n.L.data()) * Eigen::Map<const Eigen::Matrix<double, p, 1>>(xp);
  }
};

class BaraffSolver final : public Solver {
 public:
  explicit BaraffSolver(double tol) : tol_(tol) {}

  void solve(const std::vector<SolveBody>& bodies, const std::vector<SolveConstraint>& cons, bool topology_changed,
             SolveResult& out) override {
    if (topology_changed || nodes_.empty() || bodies.size() != n_bodies_) build_topology(bodies, cons);
    fill_and_factor(bodies, cons);
    // Primary-only answer z0 = H_p^-1 [F; -c_p].
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const Node& n = nodes_[i];
      if (n.constraint < 0) z0_[i] = bodies[static_cast<std::size_t>(n.body)].F;
      else z0_[i] = -cons[static_cast<std::size_t>(n.constraint)].c;
    }
    solve_in_place(z0_);

    out.rank_deficiency = 0;
    out.residual = 0;
    out.lambda.resize(cons.size());
    const int k = static_cast<int>(aux_index_.size());
    if (k > 0) solve_auxiliary(bodies, cons, out);
    out.acc.resize(bodies.size());
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
      const Node& n = nodes_[i];
      if (n.constraint < 0) out.acc[static_cast<std::size_t>(n.body)] = z0_[i];
      else out.lambda[static_cast<std::size_t>(n.constraint)] = -z0_[i];  // mu = -lambda
    }
  }

 private:
  double brow(const SolveConstraint& sc, int r, const std::vector<SolveBody>& bodies, const std::vector<Vecx>& v) const {
    double s = 0;
    if (sc.a >= 0) s += sc.Ja->row(r).head(bodies[static_cast<std::size_t>(sc.a)].dof).dot(v[static_cast<std::size_t>(sc.a)]);
    if (sc.b >= 0) s += sc.Jb->row(r).head(bodies[static_cast<std::size_t>(sc.b)].dof).dot(v[static_cast<std::size_t>(sc.b)]);
    return s;
  }

  void solve_auxiliary(const std::vector<SolveBody>& bodies, const std::vector<SolveConstraint>& cons, SolveResult& out) {
    const int k = static_cast<int>(aux_index_.size());
    // Y = H_p^-1 B, one column per auxiliary row (B = [J_x^T; 0]).
    Y_.resize(static_cast<std::size_t>(k));
    for (int col = 0; col < k; ++col) {
      auto& y = Y_[static_cast<std::size_t>(col)];
      y.resize(nodes_.size());
      for (std::size_t i = 0; i < nodes_.size(); ++i) y[i].setZero(nodes_[i].dim);
      const auto [j, r] = aux_index_[static_cast<std::size_t>(col)];
      const SolveConstraint& sc = cons[j];
      if (sc.a >= 0) y[static_cast<std::size_t>(sc.a)] += sc.Ja->row(r).head(bodies[static_cast<std::size_t>(sc.a)].dof).transpose();
      if (sc.b >= 0) y[static_cast<std::size_t>(sc.b)] += sc.Jb->row(r).head(bodies[static_cast<std::size_t>(sc.b)].dof).transpose();
      solve_in_place(y);
    }
    // K lambda_x = -(c_x + J_x xdd0), K = B^T Y (symmetric PSD).
    Eigen::MatrixXd K(k, k);
    Eigen::VectorXd r(k);
    for (int row = 0; row < k; ++row) {
      const auto [j, rr] = aux_index_[static_cast<std::size_t>(row)];
      for (int col = 0; col < k; ++col) K(row, col) = brow(cons[j], rr, bodies, Y_[static_cast<std::size_t>(col)]);
      r[row] = -(cons[j].c[rr] + brow(cons[j], rr, bodies, z0_));
    }
    K = 0.5 * (K + K.transpose());
    Eigen::VectorXd lx;
    out.rank_deficiency = truncated_svd_solve(K, r, tol_, lx);
    const double scale = std::max(r.cwiseAbs().maxCoeff(), 1e-9);
    out.residual = (K * lx - r).cwiseAbs().maxCoeff() / scale;
    for (int col = 0; col < k; ++col)
      for (std::size_t i = 0; i < nodes_.size(); ++i) z0_[i] += lx[col] * Y_[static_cast<std::size_t>(col)][i];
    for (int row = 0; row < k; ++row) {
      const auto [j, rr] = aux_index_[static_cast<std::size_t>(row)];
      if (out.lambda[j].size() != cons[j].rows()) out.lambda[j].setZero(cons[j].rows());
      out.lambda[j][rr] = lx[row];
    }
  }

  void build_topology(const std::vector<SolveBody>& bodies, const std::vector<SolveConstraint>& cons) {
    n_bodies_ = bodies.size();
    const std::vector<bool> primary = primary_constraints(static_cast<int>(bodies.size()), cons);
    nodes_.assign(bodies.size(), Node());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      nodes_[i].body = static_cast<int>(i);
      nodes_[i].dim = bodies[i].dof;
    }
    aux_index_.clear();
    std::vector<std::vector<int>> adj(bodies.size());
    std::vector<int> ground_nodes;  // constraint nodes attached to ground: the roots
    for (std::size_t j = 0; j < cons.size(); ++j) {
      if (!primary[j]) {
        for (int r = 0; r < cons[j].rows(); ++r) aux_index_.push_back({j, r});
        continue;
      }
      Node n;
      n.constraint = static_cast<int>(j);
      n.dim = cons[j].rows();
      const int id = static_cast<int>(nodes_.size());
      nodes_.push_back(n);
      adj.emplace_back();
      for (int body : {cons[j].a, cons[j].b}) {
        if (body < 0) continue;
        adj[static_cast<std::size_t>(body)].push_back(id);
        adj.back().push_back(body);
      }
      if (cons[j].a < 0 || cons[j].b < 0) ground_nodes.push_back(id);
    }
    // Breadth-first from the roots (a ground-attached constraint, so that no constraint
    // node is a leaf with a zero pivot; else any body). Reversed, the BFS order visits
    // children before parents.
    std::vector<bool> seen(nodes_.size(), false);
    order_.clear();
    auto bfs = [&](int root) {
      std::size_t head = order_.size();
      order_.push_back(root);
      seen[static_cast<std::size_t>(root)] = true;
      nodes_[static_cast<std::size_t>(root)].parent = -1;
      while (head < order_.size()) {
        const int i = order_[head++];
        for (int nb : adj[static_cast<std::size_t>(i)]) {
          if (seen[static_cast<std::size_t>(nb)]) continue;
          seen[static_cast<std::size_t>(nb)] = true;
          nodes_[static_cast<std::size_t>(nb)].parent = i;
          order_.push_back(nb);
        }
      }
    };
    for (int g : ground_nodes)
      if (!seen[static_cast<std::size_t>(g)]) bfs(g);
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (!seen[i]) bfs(static_cast<int>(i));
    std::reverse(order_.begin(), order_.end());
    z0_.assign(nodes_.size(), Vecx());
  }

  void fill_and_factor(const std::vector<SolveBody>& bodies, const std::vector<SolveConstraint>& cons) {
    for (Node& n : nodes_) {
      if (n.constraint < 0) n.D = bodies[static_cast<std::size_t>(n.body)].M;
      else n.D.setZero(n.dim, n.dim);
      if (n.parent < 0) continue;
      const Node& p = nodes_[static_cast<std::size_t>(n.parent)];
      // Block between a constraint and a body: J_side (rows x dof) or its transpose.
      const Node& cn = n.constraint >= 0 ? n : p;
      const Node& bn = n.constraint >= 0 ? p : n;
      const SolveConstraint& sc = cons[static_cast<std::size_t>(cn.constraint)];
      n.J = sc.a == bn.body ? sc.Ja : sc.Jb;
    }
    for (int i : order_) {
      Node& n = nodes_[static_cast<std::size_t>(i)];
      if (n.parent < 0) {
        invert_block(n);
        continue;
      }
      factor_block(n, nodes_[static_cast<std::size_t>(n.parent)].D);
    }
  }

  void solve_in_place(std::vector<Vecx>& x) const {
    for (int i : order_) {
      const Node& n = nodes_[static_cast<std::size_t>(i)];
      if (n.parent < 0) continue;
      with_sizes(n.dim, static_cast<int>(n.L.cols()),
                 PushUp{n, x[static_cast<std::size_t>(i)].data(), x[static_cast<std::size_t>(n.parent)].data()});
    }
    for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
      const Node& n = nodes_[static_cast<std::size_t>(*it)];
      Vecx& xi = x[static_cast<std::size_t>(*it)];
      solve_block(n, xi.data());
      if (n.parent < 0) continue;
      with_sizes(n.dim, static_cast<int>(n.L.cols()), PullDown{n, xi.data(), x[static_cast<std::size_t>(n.parent)].data()});
    }
  }

  double tol_;
  std::size_t n_bodies_ = 0;
  std::vector<Node> nodes_;
  std::vector<int> order_;
  std::vector<std::pair<std::size_t, int>> aux_index_;  // (constraint, row) of auxiliary rows
  std::vector<Vecx> z0_;
  std::vector<std::vector<Vecx>> Y_;
};

}  // namespace

std::unique_ptr<Solver> make_baraff_solver(double svd_tol) { return std::make_unique<BaraffSolver>(svd_tol); }

}  // namespace fest::lmfsim
