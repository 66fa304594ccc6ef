#pragma once
// The shrink-wrap polygoniser (docs/softobj.md §3; seed App. D §4.3, van Overveld &
// Wyvill's Shrinkwrap): a closed icosphere around the skeleton is moved through a
// geometric schedule of iso values V_0 -> V*, every vertex Newton-projected onto the
// current iso-surface, and adaptively refined (split chords that are too long or whose
// end normals differ by more than alpha) and coarsened, so that every vertex of the result
// lies on f = V* and every chord is acceptable.

#include <cstddef>

#include "core/mesh.hpp"
#include "softobj/field.hpp"

namespace fest::softobj {

struct ShrinkwrapOptions {
  double iso = 0;            // V* (> 0)
  double alpha_deg = 15;     // maximum angle between the normals at a chord's ends
  double lmax = 0;           // maximum chord length; 0 = rho = Q / V*
  int steps = 16;            // K iso steps
  int start_level = 1;       // icosphere subdivision level
  double relax = 0.5;        // tangential relaxation lambda; 0 = off
  bool coarsen = true;
  std::size_t max_vertices = 500000;
  double newton_tol = 1e-6;  // relative |f - V| / V at intermediate steps and of the result
  // Deviation-driven refinement (docs/softobj.md §3, step 3 (c')): when > 0, a chord is also
  // unacceptable when its midpoint lies farther than this from the surface, and a triangle
  // whose centroid does is split at its longest edge; coarsening and flips keep every new
  // chord and triangle within 0.8 of it. Absolute, in skeleton units; 0 = off.
  double max_deviation = 0;
};

struct ShrinkwrapStats {
  std::size_t splits = 0, collapses = 0;
  double v0 = 0, lmax = 0;
  double max_abs_f_err_rel = 0;
};

// Returns a closed triangle mesh with unit vertex normals n = -grad f / |grad f|. A run
// that fails is retried once with twice the iso steps and one more start-mesh level.
// Throws fest::Error(failure) when the surface is not genus 0 (vertices cannot reach it,
// folded triangles remain) or the vertex limit is exceeded; Error(bad_input) when the
// skeleton's total charge is not positive (no far-field sphere to start from).
TriMesh shrinkwrap(const Field& field, const ShrinkwrapOptions& options, ShrinkwrapStats* stats = nullptr);

// Newton projection along the gradient onto f = value (docs/softobj.md §3, step 3 (a)): returns
// false when it does not reach |f - value| <= tol value within the iteration limit.
bool project_to_iso(const Field& field, Eigen::Vector3d& r, double value, double tol, double max_step);

}  // namespace fest::softobj
