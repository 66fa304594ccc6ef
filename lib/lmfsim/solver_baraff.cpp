// Baraff's linear-time solver (Baraff 1996; spec §2.3). The KKT matrix
//   H = [[M, J^T], [J, 0]]
// restricted to the primary constraints is the adjacency pattern of a forest whose
// nodes are bodies and constraints. Eliminating children before parents (block LDL^T)
// costs O(n) with blocks of at most 6x6. Auxiliary rows (loops, redundancies) enter
// through the k x k Schur complement K = B^T H_p^-1 B, solved by truncated SVD so that
// redundant or ill-conditioned loops lose rank gracefully instead of failing.
#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "lmfsim/solver.hpp"

namespace fest::lmfsim {
namespace {

struct Node {
  int dim = 0;
  int parent = -1;
  int constraint = -1;  // index into cons for constraint nodes, -1 for bodies
  int body = -1;        // index of the body for body nodes
  Blk Hp;               // H_ip: dim x dim(parent)
  Blk D, Dinv, L;
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
      const Blk* J = sc.a == bn.body ? sc.Ja : sc.Jb;
      const int dof = bodies[static_cast<std::size_t>(bn.body)].dof;
      if (n.constraint >= 0) n.Hp = J->leftCols(dof);
      else n.Hp = J->leftCols(dof).transpose();
    }
    for (int i : order_) {
      Node& n = nodes_[static_cast<std::size_t>(i)];
      n.Dinv = n.D.inverse();
      if (n.parent < 0) continue;
      n.L.noalias() = n.Dinv * n.Hp;
      nodes_[static_cast<std::size_t>(n.parent)].D.noalias() -= n.Hp.transpose() * n.L;
    }
  }

  void solve_in_place(std::vector<Vecx>& x) const {
    for (int i : order_) {
      const Node& n = nodes_[static_cast<std::size_t>(i)];
      if (n.parent >= 0) x[static_cast<std::size_t>(n.parent)].noalias() -= n.L.transpose() * x[static_cast<std::size_t>(i)];
    }
    for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
      const Node& n = nodes_[static_cast<std::size_t>(*it)];
      Vecx& xi = x[static_cast<std::size_t>(*it)];
      xi = n.Dinv * xi;
      if (n.parent >= 0) xi.noalias() -= n.L * x[static_cast<std::size_t>(n.parent)];
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
