#pragma once
// A bounding-volume hierarchy over triangles answering "closest point on the surface".
// Median split on the longest axis; leaves of up to 4 triangles.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fest::compare {

using Vec3 = Eigen::Vector3d;

struct Triangle {
  Vec3 a, b, c;
};

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleTree {
 public:
  explicit TriangleTree(std::vector<Triangle> triangles);

  // Squared distance from p to the nearest triangle; +inf for an empty tree.
  double squared_distance(const Vec3& p) const;

  std::size_t size() const noexcept { return triangles_.size(); }

 private:
  struct Node {
    Eigen::AlignedBox3d box;
    std::uint32_t first = 0;  // leaf: first triangle; inner: left child
    std::uint32_t count = 0;  // leaf: triangle count; inner: 0
    std::uint32_t right = 0;  // inner: right child
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count);

  std::vector<Triangle> triangles_;
  std::vector<Node> nodes_;
};

}  // namespace fest::compare
