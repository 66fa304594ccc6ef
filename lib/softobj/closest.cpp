#include "softobj/closest.hpp"

#include <algorithm>

#include "core/closest_point.hpp"

namespace fest::softobj {

Eigen::Vector3d closest_on_segment(const Eigen::Vector3d& r, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 <= 0) return a;
  const double t = std::clamp((r - a).dot(ab) / len2, 0.0, 1.0);
  return a + t * ab;
}

// Ericson's ClosestPtPointTriangle (lib/core/closest_point.hpp), the face region by the
// normalised barycentric weights.
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c) {
  return fest::closest_point_on_triangle(p, a, b, c);
}

}  // namespace fest::softobj
