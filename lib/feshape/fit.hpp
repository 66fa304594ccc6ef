#pragma once
// The fitting schedule and the hierarchy (seed App. C §1, §5; docs/feshape.md §2.3):
// level G (global parameters and pose only), level 0 (global + local displacements on
// the initial mesh), levels 1..L (elements near far data points bisected by Rivara's
// algorithm, then fitted again). Each level's model and error statistics are returned.

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/progress_callback.hpp"
#include "feshape/assignment.hpp"
#include "feshape/dynamics.hpp"
#include "feshape/model.hpp"
#include "feshape/stiffness.hpp"

namespace fest::feshape {

enum class Solver {
  equilibrium,    // Levenberg-Marquardt on the globals + sparse solve for q_d (ours, default)
  explicit_euler, // the seed's explicit Euler on D q' + K q = f
  semi_implicit,  // explicit for the globals, (D + dt K) q_d+ = D q_d + dt f_d
};

struct FitOptions {
  StiffnessWeights weights;
  double beta = 20;                // force strength (eq. 10)
  Solver solver = Solver::equilibrium;
  double dt = 1e-5;                // Euler step (explicit solvers)
  Damping damping;                 // D (explicit solvers)
  double move_tol = 5e-5;          // converged when no node moves farther in one iteration
  int max_iter = 200;              // per level
  int levels = 3;                  // subdivision levels after level 0
  double tau = 0.05;               // points farther than this select elements (§2.1)
  std::size_t max_nodes = 100000;
  int reassign_every = 1;          // force assignment every k iterations (§1.4)
  bool global_phase = true;        // level G before level 0
  int threads = 1;
  ProgressFn progress;             // thousandths: one equal share per level (G, 0, 1, ...),
                                   // within it the iterations of max_iter
};

struct LevelResult {
  std::string name;            // "G", "0", "1", ...
  Model model;
  std::size_t selected = 0;    // elements selected for the bisection that made this level
  int iterations = 0;
  bool converged = false;      // the move tolerance was reached before max_iter
  ErrorStats error;            // distances of the data points to this level's mesh
  double surface_rms = -1;     // level G: RMS distance to the smooth global surface
  std::size_t folded = 0;      // elements whose normal opposes their global-shape normal
  double time_s = 0;
};

// Elements turned over by the local displacements: the normal of the flat triangle
// x_i = c + R(s_i + d_i) points against the normal of the same triangle on the global
// shape (d = 0). Folds mean the stiffness is too weak for the data (docs/feshape.md §1.5).
std::size_t count_folded(const Model& m);

// Fits `initial` to the points and returns every level. Stops early (fewer levels) when no
// point is farther than tau. Fails with Status::failure on numerical breakdown or when
// the node limit is reached (the levels made so far are passed to on_level first).
std::vector<LevelResult> fit(const std::vector<Eigen::Vector3d>& points, Model initial, const FitOptions& options,
                             const std::function<void(const LevelResult&)>& on_level = {});

}  // namespace fest::feshape
