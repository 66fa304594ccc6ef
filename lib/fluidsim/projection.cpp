#include "fluidsim/projection.hpp"

#include <cmath>
#include <exception>
#include <map>

#include "core/error.hpp"
#include "fluidsim/multigrid.hpp"
#include "fluidsim/operators.hpp"

namespace fest::fluidsim {

const char* poisson_name(PoissonSolver s) noexcept {
  switch (s) {
    case PoissonSolver::fdm: return "fdm";
    case PoissonSolver::fft: return "fft";
    case PoissonSolver::mg: return "mg";
    case PoissonSolver::gs: return "gs";
    case PoissonSolver::jacobi: return "jacobi";
  }
  return "?";
}

bool fft_friendly(int n) noexcept {
  auto smooth = [](int m) {
    for (int p : {2, 3, 5, 7})
      while (m % p == 0) m /= p;
    return m == 1;
  };
  return smooth(n + 1);
}

int nearest_fft_friendly(int n) noexcept {
  for (int d = 0;; ++d) {
    if (n - d >= 3 && fft_friendly(n - d)) return n - d;
    if (fft_friendly(n + d)) return n + d;
  }
}

int classes_along(const Layout& L, int axis, int reach) {
  if (!L.active(axis) || reach == 1) return 1;
  if (L.bc[axis] == Boundary::periodic && L.n[axis] % 2 == 1) return 1;  // wrap joins parities
  return 2;
}

std::vector<int> class_nodes(const Layout& L, int axis, int parity, int reach) {
  std::vector<int> nodes;
  if (reach == 2 && L.active(axis) && L.bc[axis] == Boundary::periodic && L.n[axis] % 2 == 1) {
    // One class walked in steps of 2 around the odd cycle (0, 2, ..., n-1, 1, 3, ...), so
    // the stencil's neighbours are adjacent in the class as in every other class.
    for (int k = 0; k < L.n[axis]; ++k) nodes.push_back((2 * k) % L.n[axis]);
    return nodes;
  }
  const int step = classes_along(L, axis, reach) == 2 ? 2 : 1;
  for (int i = step == 2 ? parity : 0; i < L.size[axis]; i += step) nodes.push_back(i);
  return nodes;
}

Projector::Projector(const Layout& layout, const ProjectionOptions& options)
    : layout_(layout), options_(options), reach_(options.compact ? 1 : 2) {
  for (int a = 0; a < 3; ++a) nb_[a] = neighbours(layout_, a, reach_);
  if (options_.solver == PoissonSolver::gs || options_.solver == PoissonSolver::jacobi) return;

  const Transform kind = options_.solver == PoissonSolver::fft ? Transform::fftw : Transform::dense;
  std::map<std::pair<int, int>, std::shared_ptr<const AxisBasis>> bases;  // (axis, parity)
  auto basis = [&](int axis, int parity) {
    auto key = std::make_pair(axis, parity);
    auto it = bases.find(key);
    if (it != bases.end()) return it->second;
    auto b = std::make_shared<const AxisBasis>(layout_, axis, class_nodes(layout_, axis, parity, reach_), reach_,
                                               Parity::even, kind);
    bases.emplace(key, b);
    return std::shared_ptr<const AxisBasis>(b);
  };
  for (int p2 = 0; p2 < classes_along(layout_, 2, reach_); ++p2)
    for (int p1 = 0; p1 < classes_along(layout_, 1, reach_); ++p1)
      for (int p0 = 0; p0 < classes_along(layout_, 0, reach_); ++p0) {
        std::array<std::shared_ptr<const AxisBasis>, 3> axes{basis(0, p0), basis(1, p1), basis(2, p2)};
        if (options_.solver == PoissonSolver::mg)
          multigrid_.push_back(std::make_unique<MultigridClass>(layout_, axes, options_.tol));
        else
          classes_.push_back(std::make_unique<BoxSolver>(axes, 0.0, 1.0));
      }
}

Projector::~Projector() = default;

std::array<int, 3> Projector::class_size(int c) const {
  const auto& axes = classes_[c]->axes();
  return {axes[0]->size(), axes[1]->size(), axes[2]->size()};
}

void Projector::apply_laplacian(const Field& q, Field& out) const {
  const Layout& L = layout_;
  out.assign(L.count(), 0.0);
  const double c = 1.0 / ((reach_ * L.h) * (reach_ * L.h));
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
  for (int k = 0; k < L.size[2]; ++k)
    for (int j = 0; j < L.size[1]; ++j)
      for (int i = 0; i < L.size[0]; ++i) {
        const int ijk[3] = {i, j, k};
        const double centre = q[L.index(i, j, k)];
        double s = 0.0;
        for (int a = 0; a < L.dim; ++a) {
          int p[3] = {i, j, k}, m[3] = {i, j, k};
          p[a] = nb_[a].plus[ijk[a]];
          m[a] = nb_[a].minus[ijk[a]];
          s += c * (q[L.index(p[0], p[1], p[2])] + q[L.index(m[0], m[1], m[2])] - 2.0 * centre);
        }
        out[L.index(i, j, k)] = s;
      }
}

// Gauss-Seidel (lexicographic, as Stam's code) or Jacobi sweeps from q = 0: the
// approximate projections the anchors use.
int Projector::iterate(const Field& rhs, Field& q) const {
  const Layout& L = layout_;
  const double c = 1.0 / ((reach_ * L.h) * (reach_ * L.h));
  q.assign(L.count(), 0.0);
  Field next;
  const bool jacobi = options_.solver == PoissonSolver::jacobi;
  auto relax = [&](const Field& from, Field& to, int i, int j, int k) {
    const int ijk[3] = {i, j, k};
    double off = 0.0, diag = 0.0;
    for (int a = 0; a < L.dim; ++a) {
      diag -= 2.0 * c;
      for (int side = 0; side < 2; ++side) {
        int p[3] = {i, j, k};
        p[a] = side == 0 ? nb_[a].plus[ijk[a]] : nb_[a].minus[ijk[a]];
        if (p[a] == ijk[a])
          diag += c;  // a mirror that folds back onto the node itself
        else
          off += c * from[L.index(p[0], p[1], p[2])];
      }
    }
    const std::size_t n = L.index(i, j, k);
    to[n] = (rhs[n] - off) / diag;
  };
  for (int it = 0; it < options_.iters; ++it) {
    if (jacobi) {
      next.resize(q.size());
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
      for (int k = 0; k < L.size[2]; ++k)
        for (int j = 0; j < L.size[1]; ++j)
          for (int i = 0; i < L.size[0]; ++i) relax(q, next, i, j, k);
      q.swap(next);
    } else {
      for (int k = 0; k < L.size[2]; ++k)
        for (int j = 0; j < L.size[1]; ++j)
          for (int i = 0; i < L.size[0]; ++i) relax(q, q, i, j, k);
    }
  }
  return options_.iters;
}

int Projector::solve(const Field& rhs, Field& q) const {
  if (options_.solver == PoissonSolver::gs || options_.solver == PoissonSolver::jacobi) return iterate(rhs, q);
  // Zeros where no class writes (outside the boxes), filled by the team: q is kept from
  // step to step, so this is the only pass over it before the solve.
  if (q.size() != layout_.count()) q.resize(layout_.count());
  double* qv = q.data();
#pragma omp parallel for schedule(static) if (layout_.count() >= kParallelNodes)
  for (std::size_t n = 0; n < layout_.count(); ++n) qv[n] = 0.0;
  if (!multigrid_.empty()) {
    int cycles = 0;
    std::exception_ptr failure;
    // The 2^d classes are independent: one task each (the seed's 8 sub-tasks).
#pragma omp parallel for schedule(dynamic, 1) reduction(max : cycles) if (layout_.count() >= kParallelNodes)
    for (int c = 0; c < static_cast<int>(multigrid_.size()); ++c) {
      try {
        cycles = std::max(cycles, multigrid_[c]->solve(layout_, rhs, q));
      } catch (...) {
#pragma omp critical(fluidsim_mg_failure)
        failure = std::current_exception();
      }
    }
    if (failure) std::rethrow_exception(failure);
    return cycles;
  }
  // All classes stage by stage, the pieces of every class's transforms and eliminations
  // shared by the whole team: 8 class tasks would leave threads beyond 8 idle and balance
  // badly at any count that does not divide 8.
  std::vector<BoxJob> jobs;
  for (const auto& c : classes_) jobs.push_back({c.get(), &rhs, &q});
  BoxSolver::solve_all(layout_, jobs, &buffers_);
  return 0;
}

ProjectionStats Projector::project(Velocity& u) const {
  ProjectionStats st;
  enforce_walls(layout_, u);
  Field& div = div_;  // kept between calls: fresh ones are zero-filled by one thread
  Field& q = q_;
  divergence(layout_, u, div);
  st.max_div_before = max_abs(div);
  st.iterations = solve(div, q);
  subtract_gradient(layout_, q, u);
  enforce_walls(layout_, u);
  st.max_div_after = max_abs_divergence(layout_, u);
  return st;
}

}  // namespace fest::fluidsim
