#pragma once
// A bounding-volume hierarchy over triangles for shadow rays (docs/radiosity.md §3,
// ray-cast form factors and §5 gathering): median splits on the longest axis, an
// any-hit query for a segment.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "radiosity/model.hpp"

namespace fest::radiosity {

class Bvh {
 public:
  Bvh() = default;
  // Quads become two triangles.
  explicit Bvh(const std::vector<Polygon>& polygons);

  // True when a triangle crosses the open segment from a to b (excluding its ends).
  bool occluded(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  std::size_t triangles() const { return tris_.size(); }

 private:
  struct Tri {
    Eigen::Vector3d p0, e1, e2;
  };
  struct Node {
    Eigen::Vector3d lo, hi;
    int left = -1, right = -1;  // children, or -1 for a leaf
    int first = 0, count = 0;   // leaf triangles
  };
  int build(int first, int count, std::vector<Eigen::Vector3d>& centres, int depth);

  std::vector<Tri> tris_;
  std::vector<Node> nodes_;
};

}  // namespace fest::radiosity
