#include "fluidsim/multigrid.hpp"

#include <cmath>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "core/error.hpp"

namespace fest::fluidsim {

using Sparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct MultigridClass::Level {
  Sparse A;          // weighted (symmetric) operator of this level
  Sparse P;          // interpolation from the next coarser level (empty on the last)
  Sparse R;          // P^T
  std::array<int, 3> m{1, 1, 1};
};

namespace {

// 1-D linear interpolation from every other node; a trailing fine node with no right
// coarse neighbour copies its left one (constants stay constants).
Sparse interpolation_1d(int m, bool periodic, int& mc) {
  mc = (m + 1) / 2;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < m; ++i) {
    if (i % 2 == 0) {
      t.emplace_back(i, i / 2, 1.0);
    } else if (i + 1 < m) {
      t.emplace_back(i, (i - 1) / 2, 0.5);
      t.emplace_back(i, (i + 1) / 2, 0.5);
    } else if (periodic) {
      t.emplace_back(i, (i - 1) / 2, 0.5);
      t.emplace_back(i, 0, 0.5);
    } else {
      t.emplace_back(i, (i - 1) / 2, 1.0);
    }
  }
  Sparse P(m, mc);
  P.setFromTriplets(t.begin(), t.end());
  return P;
}

void gauss_seidel(const Sparse& A, const Eigen::VectorXd& b, Eigen::VectorXd& x, bool backward) {
  const int n = static_cast<int>(A.rows());
  for (int s = 0; s < n; ++s) {
    const int r = backward ? n - 1 - s : s;
    double diag = 0.0, sum = b[r];
    for (Sparse::InnerIterator it(A, r); it; ++it) {
      if (it.col() == r)
        diag = it.value();
      else
        sum -= it.value() * x[it.col()];
    }
    if (diag != 0.0) x[r] = sum / diag;
  }
}

}  // namespace

MultigridClass::MultigridClass(const Layout& layout, const std::array<std::shared_ptr<const AxisBasis>, 3>& axes,
                               double tol)
    : tol_(tol) {
  std::array<int, 3> m{};
  for (int a = 0; a < 3; ++a) {
    nodes_[a] = axes[a]->nodes();
    m[a] = axes[a]->size();
  }
  const std::size_t count = static_cast<std::size_t>(m[0]) * m[1] * m[2];
  weight_.resize(count);
  std::vector<Eigen::Triplet<double>> t;
  std::size_t row = 0;
  for (int k = 0; k < m[2]; ++k)
    for (int j = 0; j < m[1]; ++j)
      for (int i = 0; i < m[0]; ++i, ++row) {
        const int ijk[3] = {i, j, k};
        double w = 1.0;
        for (int a = 0; a < 3; ++a)
          if (layout.is_wall(a, nodes_[a][ijk[a]])) w *= 0.5;
        weight_[row] = w;
        for (int a = 0; a < 3; ++a) {
          const auto& T = axes[a]->matrix();
          for (int col = 0; col < m[a]; ++col) {
            const double v = T[static_cast<std::size_t>(ijk[a]) * m[a] + col];
            if (v == 0.0) continue;
            int c[3] = {i, j, k};
            c[a] = col;
            t.emplace_back(static_cast<int>(row), c[0] + m[0] * (c[1] + m[1] * c[2]), w * v);
          }
        }
      }
  auto level = std::make_unique<Level>();
  level->A.resize(static_cast<Eigen::Index>(count), static_cast<Eigen::Index>(count));
  level->A.setFromTriplets(t.begin(), t.end());
  level->m = m;
  levels_.push_back(std::move(level));

  // Coarsen until the level is small enough for a dense pseudo-inverse.
  for (;;) {
    Level& fine = *levels_.back();
    const std::array<int, 3> mf = fine.m;
    if (static_cast<std::size_t>(mf[0]) * mf[1] * mf[2] <= 64) break;
    std::array<Sparse, 3> P1;
    std::array<int, 3> mc{};
    for (int a = 0; a < 3; ++a) {
      if (mf[a] <= 3) {
        mc[a] = mf[a];
        P1[a].resize(mf[a], mf[a]);
        P1[a].setIdentity();
      } else {
        P1[a] = interpolation_1d(mf[a], layout.bc[a] == Boundary::periodic, mc[a]);
      }
    }
    std::vector<Eigen::Triplet<double>> pt;
    int fr = 0;
    for (int k = 0; k < mf[2]; ++k)
      for (int j = 0; j < mf[1]; ++j)
        for (int i = 0; i < mf[0]; ++i, ++fr)
          for (Sparse::InnerIterator ik(P1[2], k); ik; ++ik)
            for (Sparse::InnerIterator ij(P1[1], j); ij; ++ij)
              for (Sparse::InnerIterator ii(P1[0], i); ii; ++ii)
                pt.emplace_back(fr, static_cast<int>(ii.col() + mc[0] * (ij.col() + mc[1] * ik.col())),
                                ii.value() * ij.value() * ik.value());
    fine.P.resize(fr, mc[0] * mc[1] * mc[2]);
    fine.P.setFromTriplets(pt.begin(), pt.end());
    fine.R = fine.P.transpose();
    auto coarse = std::make_unique<Level>();
    const Sparse AP = fine.A * fine.P;
    coarse->A = fine.R * AP;
    coarse->A.prune(0.0);
    coarse->m = mc;
    levels_.push_back(std::move(coarse));
  }
  const Eigen::MatrixXd dense = Eigen::MatrixXd(levels_.back()->A);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense);
  const Eigen::VectorXd& l = eig.eigenvalues();
  const double lmax = l.cwiseAbs().maxCoeff();
  Eigen::VectorXd inv(l.size());
  for (int i = 0; i < l.size(); ++i) inv[i] = std::fabs(l[i]) <= 1e-10 * lmax ? 0.0 : 1.0 / l[i];
  const Eigen::MatrixXd pinv = eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
  coarse_pinv_.assign(pinv.data(), pinv.data() + pinv.size());
}

MultigridClass::~MultigridClass() = default;

int MultigridClass::solve(const Layout& layout, const Field& rhs, Field& q) const {
  const auto& n0 = nodes_[0];
  const auto& n1 = nodes_[1];
  const auto& n2 = nodes_[2];
  const Eigen::Index count = static_cast<Eigen::Index>(weight_.size());
  Eigen::VectorXd b(count);
  Eigen::Index r = 0;
  for (int k : n2)
    for (int j : n1)
      for (int i : n0) {
        b[r] = weight_[r] * rhs[layout.index(i, j, k)];
        ++r;
      }
  const int L = static_cast<int>(levels_.size());
  const Eigen::Index last_n = levels_.back()->A.rows();
  Eigen::Map<const Eigen::MatrixXd> pinv(coarse_pinv_.data(), last_n, last_n);

  // One V(2,2) cycle, recursive over the levels.
  auto vcycle = [&](auto&& self, int l, const Eigen::VectorXd& bl, Eigen::VectorXd& x) -> void {
    const Level& lv = *levels_[l];
    if (l == L - 1) {
      x = pinv * bl;
      return;
    }
    for (int s = 0; s < 2; ++s) gauss_seidel(lv.A, bl, x, false);
    const Eigen::VectorXd res = bl - lv.A * x;
    const Eigen::VectorXd bc = lv.R * res;
    Eigen::VectorXd xc = Eigen::VectorXd::Zero(bc.size());
    self(self, l + 1, bc, xc);
    x += lv.P * xc;
    for (int s = 0; s < 2; ++s) gauss_seidel(lv.A, bl, x, true);
  };

  // A singular class (Neumann or periodic: the constants are the null space of the
  // symmetric weighted operator) is solvable only for b orthogonal to the constants; the
  // exact right-hand side is, up to rounding, which would stall the iteration.
  const bool singular = std::fabs((levels_[0]->A * Eigen::VectorXd::Ones(count)).sum()) <
                        1e-9 * std::max(1e-300, levels_[0]->A.norm());
  if (singular) b.array() -= b.mean();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(count);
  const double bnorm = b.norm();
  int cycles = 0;
  if (bnorm > 0.0) {
    while ((b - levels_[0]->A * x).norm() > tol_ * bnorm) {
      if (++cycles > 200) throw runtime_failure("multigrid did not reach the relative residual {} in 200 V-cycles", tol_);
      vcycle(vcycle, 0, b, x);
    }
  }
  // The null space: weighted mean 0, the same normalisation as the direct solvers.
  double sw = 0.0, swx = 0.0;
  for (Eigen::Index i = 0; i < count; ++i) {
    sw += weight_[i];
    swx += weight_[i] * x[i];
  }
  if (singular) x.array() -= swx / sw;
  r = 0;
  for (int k : n2)
    for (int j : n1)
      for (int i : n0) q[layout.index(i, j, k)] = x[r++];
  return cycles;
}

}  // namespace fest::fluidsim
