#pragma once
// Progressive refinement radiosity (docs/radiosity.md §4) with the four shot rules
//
//   pr        s = U_i                                   (Cohen et al. 1988, Southwell)
//   sor       s = omega U_i                             (Gortler et al. 1993)
//   overshoot s = U_i + rho_i sum_k F_{i->k} max(U_k, 0) (Feda & Purgathofer 1992)
//   orpr      s = U_i + omega rho_i sum_k F_{i->k} U_k   (over-relaxed PR, §4)
//
// keeping the invariant B = E + rho F (B - U) (everything in B except U has been shot),
// and adaptive element subdivision (§5) between rounds of shooting.

#include <functional>
#include <string>
#include <vector>

#include "radiosity/form_factors.hpp"
#include "radiosity/model.hpp"

namespace fest::radiosity {

enum class Solver { pr, sor, overshoot, orpr };
const char* solver_name(Solver s);

struct ShotRecord {
  long shot = 0;           // 1-based
  int patch = -1;
  int object = -1;
  double unshot_fraction = 0;  // sum_p A_p sum_rgb |U_p| / sum_p A_p sum_rgb E_p after the shot
  double omega = 1;            // the over-relaxation in effect (1 for pr and overshoot)
  double seconds = 0;          // since the solve began
  double shot_energy = 0;      // A_i sum_rgb |s|
  double received_energy = 0;  // sum_e A_e F_{e->i} sum_rgb |s| (the shot's irradiance, area-weighted)
  double row_sum = 0;          // sum_k F_{i->k}
  int level = 0;
};

struct SolveOptions {
  Solver solver = Solver::orpr;
  double omega = -1;      // < 0: the solver's default (orpr 1.0, sor 1.5)
  double tol = 1e-3;
  long max_shots = 0;     // 0: 10 x patches (per level)
  int levels = 0;         // adaptive subdivision rounds (§5)
  double grad = 0.05;     // split elements whose relative luminance step exceeds this
  double min_element = 0; // do not split elements whose longest edge is at most this
  int threads = 1;
  std::function<void(const ShotRecord&, const Model&)> on_shot;  // after every shot
};

struct SolveStats {
  long shots = 0;
  bool converged = false;
  bool fell_back = false;           // the divergence safeguard switched to pr
  double visibility_seconds = 0;    // form factors (hemicube rasterisation / ray casting)
  double solve_seconds = 0;         // shot arithmetic
  double subdivision_seconds = 0;   // adaptive splitting and gathering
  double unshot_fraction = 0;
  std::vector<long> elements_per_level;
  std::vector<long> shots_per_level;
};

// Solves from the model's current state (build_model leaves B = E, U = E).
SolveStats solve(Model& model, FormFactors& ff, const SolveOptions& options);

// Vertex luminance gradients and the split of one round of §5; returns elements split.
long subdivide(Model& model, const FormFactors& ff, double grad, double min_element, int threads);

}  // namespace fest::radiosity
