#pragma once
// The deformable model of seed App. C §3 (docs/feshape.md §1.1-1.3): rigid pose
// (centre c, unit quaternion), the 11 global parameters, and the finite-element mesh in
// material coordinates with one local displacement d_i (model frame) per node.
// x(u) = c + R (s(u) + d(u))  (eq. 1).

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "feshape/superquadric.hpp"
#include "feshape/triangulation.hpp"

namespace fest::feshape {

struct Model {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  GlobalParams qs{1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0};
  Triangulation mesh;
  std::vector<Eigen::Vector3d> d;  // local displacement per node, model frame

  // World position of node i: c + R (s(u_i) + d_i).
  Eigen::Vector3d node_position(std::size_t i) const;
  std::vector<Eigen::Vector3d> node_positions() const;
  // The global (smooth) surface point at (u, v), without local displacement.
  Eigen::Vector3d global_point(double u, double v) const;
};

// A model on the lat-long mesh with zero local displacements.
Model make_model(int rings, int meridians, const GlobalParams& qs, const Eigen::Vector3d& center,
                 const Eigen::Quaterniond& rotation);

// Gives the nodes that refinement appended (mesh already holds their u, v) the
// displacement that keeps the surface where it was: d_D = R^T((x_A + x_B)/2 - c) - s(u_D)
// (docs/feshape.md §2.2).
struct NewNode;
void displace_new_nodes(Model& m, const std::vector<Eigen::Vector3d>& old_positions, const std::vector<NewNode>& created);

// --init auto (docs/feshape.md §2.3): centre = centroid, axes = principal axes with
// axis 3 along the largest variance, a = largest half-extent, a_i = half-extents / a,
// e1 = e2 = 1, no tapering or bending, b3 = 1. Fails (Status::failure) for coincident or
// collinear points.
void auto_initialize(const std::vector<Eigen::Vector3d>& points, Model& m);

}  // namespace fest::feshape
