#pragma once
// Mesh simplification by edge collapses ordered by quadric error (Garland & Heckbert 1997,
// with the attribute quadrics of their 1998 paper): see docs/decimate.md.
//
// The engine collapses one halfedge at a time (the surviving vertex is moved to the
// quadric-optimal position), refuses collapses that break the link condition (the
// surface would stop being a 2-manifold) or that turn a face over, keeps boundaries and
// sharp features in place through constraint planes or by locking their vertices, and
// stops at a face count or when the cheapest collapse would exceed an error bound.

#include <cstddef>

#include "core/mesh.hpp"
#include "core/progress_callback.hpp"

namespace fest::decimate {

// Weight of a face's plane in the vertex quadrics.
enum class Weighting { area, sqrt_area, uniform };

struct SimplifyOptions {
  std::size_t target_faces = 0;   // stop at or below this many faces (0: no face target)
  double max_error = -1;          // stop before a collapse whose error estimate exceeds this (< 0: none)
  bool use_normals = true;        // attribute quadrics over what the mesh has (GH98)
  bool use_colors = true;
  bool use_texcoords = true;
  double attribute_weight = 1.0;  // scale of attribute differences against lengths (in bbox diagonals)
  bool lock_boundary = false;     // boundary vertices never move
  bool lock_features = false;     // vertices on feature edges never move
  double feature_angle_deg = 180; // dihedral angle above which an edge is a feature (180: none)
  double constraint_weight = 1000;// weight of the boundary/feature constraint planes (GH97 6)
  double min_normal_cos = 0.0;    // a collapse may turn no face by more than acos(this)
  bool optimal_placement = true;  // false: surviving vertex stays where it is (half-edge collapse)
  Weighting weighting = Weighting::sqrt_area;  // area: GH97 section 7; uniform: each plane once
  // Faces removed of those to remove (input - target_faces; without a face target, of
  // the input's: an error bound ends the run before).
  ProgressFn progress;
};

struct SimplifyStats {
  std::size_t input_faces = 0, output_faces = 0;
  std::size_t input_vertices = 0, output_vertices = 0;
  std::size_t triangulated_polygons = 0;  // polygons split into triangles before simplifying
  std::size_t collapses = 0;
  std::size_t rejected_link = 0, rejected_flip = 0, rejected_locked = 0;
  std::size_t locked_vertices = 0, feature_edges = 0, boundary_edges = 0;
  double max_error_estimate = 0;  // largest estimate of a performed collapse (see error_estimate)
  bool reached_target = false;
  int dimension = 3;              // n of the quadrics (3 + attributes)
};

// Simplifies `mesh` (polygons are fan-triangulated first). Vertex normals, colours and
// texture coordinates of surviving vertices are set from the optimal point in R^n; face
// colours and normals stay with their faces. Throws fest::Error(bad_input) for non-finite
// coordinates. Deterministic: ties are broken by edge index.
Mesh simplify(const Mesh& mesh, const SimplifyOptions& options, SimplifyStats* stats = nullptr);

}  // namespace fest::decimate
