#include "feshape/fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "feshape/global_fit.hpp"
#include "feshape/local_fit.hpp"
#include "feshape/refine.hpp"

namespace fest::feshape {
namespace {

double max_move(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, (a[i] - b[i]).norm());
  return m;
}

void check_finite(const Model& m) {
  bool ok = m.center.allFinite() && m.rotation.coeffs().allFinite();
  for (double q : m.qs) ok = ok && std::isfinite(q);
  for (const auto& d : m.d) ok = ok && d.allFinite();
  if (!ok) throw make_error(Status::failure, "the model became non-finite (NaN) during fitting");
}

// Level G with the equilibrium solver: the smooth surface, data points projected onto it.
int fit_global_smooth(Model& m, const std::vector<Eigen::Vector3d>& points, const FitOptions& o, bool& converged,
                      double& surface_rms, const ProgressFn& progress) {
  std::vector<Eigen::Vector2d> uv(points.size());
  double mu = 1e-3, energy = 0;
  int it = 0;
  converged = false;
  std::vector<double> history;  // energy per iteration: stop when 10 iterations gain < 0.1 %
  for (; it < o.max_iter; ++it) {
    const std::vector<Eigen::Vector3d> before = m.node_positions();
    if (it % std::max(1, o.reassign_every) == 0) {
      // Fresh start points from the mesh; a warm start that is nearer stays.
      const std::vector<MeshPoint> a = assign_points(points, before, m.mesh.tris, o.threads);
      constexpr std::size_t chunk = 128;
      parallel_for((points.size() + chunk - 1) / chunk, o.threads, [&](std::size_t c) {
        for (std::size_t p = c * chunk; p < std::min(points.size(), (c + 1) * chunk); ++p) {
          Eigen::Vector2d fresh = material_point(m.mesh, a[p]);
          if (it == 0) {
            uv[p] = fresh;
            continue;
          }
          Eigen::Vector2d warm = uv[p];
          if (project_to_surface(m, points[p], fresh) < project_to_surface(m, points[p], warm)) uv[p] = fresh;
        }
      });
    }
    const bool stepped = global_step_smooth(m, points, uv, mu, energy, o.threads);
    check_finite(m);
    if (progress) progress(static_cast<std::uint64_t>(it + 1), static_cast<std::uint64_t>(o.max_iter));
    history.push_back(energy);
    const std::size_t h = history.size();
    const bool stalled = h > 10 && history[h - 11] - history[h - 1] <= 1e-3 * history[h - 11];
    if (!stepped || stalled || max_move(before, m.node_positions()) < o.move_tol) {
      converged = true;
      ++it;
      break;
    }
  }
  surface_rms = points.empty() ? 0 : std::sqrt(energy / static_cast<double>(points.size()));
  return it;
}

// A level with local displacements (or level G with the Euler solvers).
int fit_level(Model& m, const std::vector<Eigen::Vector3d>& points, const FitOptions& o, bool local,
              bool& converged, const ProgressFn& progress) {
  const Eigen::SparseMatrix<double> k = assemble_stiffness(m.mesh, o.weights);
  std::unique_ptr<EulerIntegrator> euler;
  if (o.solver != Solver::equilibrium)
    euler = std::make_unique<EulerIntegrator>(k, o.beta, o.dt, o.damping, local, o.solver == Solver::semi_implicit);
  std::vector<MeshPoint> assigned;
  std::vector<Eigen::Vector3d> normals;
  double mu = 1e-3, energy = 0;
  int it = 0;
  converged = false;
  std::vector<double> mean_history;
  for (; it < o.max_iter; ++it) {
    const std::vector<Eigen::Vector3d> before = m.node_positions();
    if (it % std::max(1, o.reassign_every) == 0) {
      assigned = assign_points(points, before, m.mesh.tris, o.threads);
      // Residual directions belong to the assignment: between reassignments the points
      // keep their elements, barycentric coordinates and directions (§1.4).
      normals = residual_directions(points, before, m.mesh.tris, assigned);
      // Stall test: points near element edges can change elements back and forth, so the
      // nodes jitter above the move tolerance while the fit no longer improves. Stop when
      // the mean distance has not fallen by 1e-4 (relative) over 10 assignments.
      mean_history.push_back(error_stats(assigned).mean);
      const std::size_t h = mean_history.size();
      if (o.solver == Solver::equilibrium && h > 10 &&
          mean_history[h - 11] - mean_history[h - 1] <= 1e-4 * mean_history[h - 11]) {
        converged = true;
        break;
      }
    }
    if (euler) {
      euler->step(m, points, assigned);
    } else {
      global_step_flat(m, points, assigned, normals, mu, energy);
      if (local) solve_local_equilibrium(m, points, assigned, normals, k, o.beta);
    }
    check_finite(m);
    if (progress && (euler == nullptr || (it + 1) % 1000 == 0))
      progress(static_cast<std::uint64_t>(it + 1), static_cast<std::uint64_t>(o.max_iter));
    if (max_move(before, m.node_positions()) < o.move_tol) {
      converged = true;
      ++it;
      break;
    }
  }
  return it;
}

}  // namespace

std::size_t count_folded(const Model& m) {
  const std::vector<Eigen::Vector3d> x = m.node_positions();
  std::vector<Eigen::Vector3d> g(x.size());
  for (std::size_t i = 0; i < g.size(); ++i) g[i] = m.global_point(m.mesh.u[i], m.mesh.v[i]);
  std::size_t folded = 0;
  for (const auto& f : m.mesh.tris) {
    const Eigen::Vector3d n = (x[f[1]] - x[f[0]]).cross(x[f[2]] - x[f[0]]);
    const Eigen::Vector3d ng = (g[f[1]] - g[f[0]]).cross(g[f[2]] - g[f[0]]);
    if (n.dot(ng) < 0) ++folded;
  }
  return folded;
}

std::vector<LevelResult> fit(const std::vector<Eigen::Vector3d>& points, Model m, const FitOptions& o,
                             const std::function<void(const LevelResult&)>& on_level) {
  std::vector<LevelResult> out;
  auto finish = [&](LevelResult r, std::chrono::steady_clock::time_point t0) {
    const std::vector<MeshPoint> a = assign_points(points, m.node_positions(), m.mesh.tris, o.threads);
    r.error = error_stats(a);
    r.folded = count_folded(m);
    r.model = m;
    r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (on_level) on_level(r);
    out.push_back(std::move(r));
    return a;
  };
  m.d.assign(m.mesh.nodes(), Eigen::Vector3d::Zero());
  const int shares = (o.global_phase ? 1 : 0) + o.levels + 1;
  int share = 0;
  auto level_progress = [&] {
    const double begin = static_cast<double>(share) / shares;
    ++share;
    return progress_part(o.progress, begin, static_cast<double>(share) / shares);
  };
  if (o.global_phase) {
    const auto t0 = std::chrono::steady_clock::now();
    LevelResult r;
    r.name = "G";
    if (o.solver == Solver::equilibrium)
      r.iterations = fit_global_smooth(m, points, o, r.converged, r.surface_rms, level_progress());
    else
      r.iterations = fit_level(m, points, o, false, r.converged, level_progress());
    finish(std::move(r), t0);
  }
  std::vector<MeshPoint> assigned;
  for (int level = 0; level <= o.levels; ++level) {
    const auto t0 = std::chrono::steady_clock::now();
    LevelResult r;
    r.name = std::to_string(level);
    if (level > 0) {
      // §2.1: elements near points still farther than tau; §2.2: bisect them.
      const std::vector<std::vector<int>> around = faces_around_nodes(m.mesh);
      std::vector<char> selected(m.mesh.elements(), 0);
      for (const MeshPoint& p : assigned)
        if (p.dist > o.tau) select_elements(m.mesh, p, around, selected);
      r.selected = static_cast<std::size_t>(std::count(selected.begin(), selected.end(), 1));
      if (r.selected == 0) break;  // every point is within tau: the hierarchy is complete
      std::vector<Eigen::Vector3d> x = m.node_positions();
      const std::vector<NewNode> created = rivara_refine(m.mesh, x, selected, o.max_nodes);
      displace_new_nodes(m, x, created);
    }
    r.iterations = fit_level(m, points, o, true, r.converged, level_progress());
    assigned = finish(std::move(r), t0);
  }
  return out;
}

}  // namespace fest::feshape
