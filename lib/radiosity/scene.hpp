#pragma once
// The input of radiosity: objects made of polygonal faces with one reflectance and one
// emission each (docs/radiosity.md §2), and the checks every scene passes before it is
// meshed (bad input is refused here, in the scene's own terms).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "radiosity/model.hpp"

namespace fest::radiosity {

struct SceneObject {
  std::string name;
  Rgb reflectance = Rgb::Zero();
  Rgb emission = Rgb::Zero();  // as the scene states it (radiance or exitance, see MeshingOptions)
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<std::uint32_t>> faces;  // polygons, counter-clockwise about the front side
};

struct Scene {
  std::string units = "m";
  std::vector<SceneObject> objects;
  double patch_size = 0;    // 0: not given
  double element_size = 0;  // 0: not given
};

struct SceneCheck {
  std::size_t faces = 0;
  std::size_t open_edges = 0;  // edges used by one face only (over all objects): the scene is not closed
  double diagonal = 0;         // bounding-box diagonal
};

// Throws fest::Error(bad_input) for: no objects or no faces, non-finite numbers, a
// reflectance outside [0, 0.999] (rho >= 1 makes the equation singular), negative
// emission, no emitter, a face index out of range, a face with fewer than 3 corners,
// zero-area faces (counted, with the first object named). An open scene is allowed:
// the count of open edges is returned for the report.
SceneCheck check_scene(const Scene& scene);

struct MeshingOptions {
  double patch_size = 0;    // 0: scene diagonal / 12 (or the scene's own)
  double element_size = 0;  // 0: patch size / 4 (or the scene's own)
  bool no_mesh = false;     // every face is one patch and one element
  bool emission_is_radiance = true;  // E = pi * emission (Cornell "17 12 4" is radiance)
};

// Splits faces into patches and elements (§2): quads into grids of quads, triangles
// (and non-planar or non-convex quads, and polygons after fan triangulation) into 4^k
// triangles. Solution values are reset (B = E, U = E).
Model build_model(const Scene& scene, const MeshingOptions& options);

// Subdivision of one polygon so that no edge is longer than `size` (quads: a grid of
// quads; triangles: uniform 4^k split). Exposed for the adaptive step and tests.
std::vector<Polygon> split_polygon(const Polygon& poly, double size);
// One level of 1 -> 4 splitting (quads by edge midpoints and centre; triangles by midpoints).
std::vector<Polygon> split_in_four(const Polygon& poly);

}  // namespace fest::radiosity
