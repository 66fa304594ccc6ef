#pragma once
// Force assignment (seed App. C §4.2, docs/feshape.md §1.4) and the error statistics of
// Tables 1-2 (§2.4): every data point is attached to the closest point of the model's
// flat triangles.

#include <vector>

#include <Eigen/Core>

#include "feshape/closest.hpp"
#include "feshape/triangulation.hpp"

namespace fest::feshape {

// Closest mesh point (element, barycentric coordinates, distance) of every data point
// (eq. 9), through an AABB tree; split over `threads`, the same answer for any count.
std::vector<MeshPoint> assign_points(const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<Eigen::Vector3d>& positions,
                                     const std::vector<std::array<int, 3>>& tris, int threads);

// Material coordinates of a mesh point: u_z = sum lambda_i u_i, seam- and pole-aware.
Eigen::Vector2d material_point(const Triangulation& t, const MeshPoint& p);

// Distances of the data points to a mesh: mean, max, standard deviation, variance.
struct ErrorStats {
  std::size_t count = 0;
  double mean = 0, max = 0, std = 0, var = 0;
};
ErrorStats error_stats(const std::vector<MeshPoint>& assigned);

}  // namespace fest::feshape
