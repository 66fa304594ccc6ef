#pragma once
// Closest points on skeleton primitives (docs/softobj.md §1): point-segment by clamped
// projection, point-triangle by the Voronoi-region test (Ericson, Real-Time Collision
// Detection, 5.1.5).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fest::softobj {

Eigen::Vector3d closest_on_segment(const Eigen::Vector3d& r, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& r, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c);

}  // namespace fest::softobj
