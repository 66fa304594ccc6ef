#pragma once
// Closest points on the model's flat triangles (seed App. C eq. 9): per triangle
// (Ericson's region test, barycentric result) and over all triangles through an AABB
// tree (docs/feshape.md §1.4: O(n log m) instead of the seed's O(mn) search).

#include <array>
#include <vector>

#include <Eigen/Core>

namespace fest::feshape {

struct TrianglePoint {
  std::array<double, 3> lambda{};  // barycentric coordinates of the closest point
  double dist2 = 0;                // squared distance
};
TrianglePoint closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& c);

struct MeshPoint {
  int face = -1;
  std::array<double, 3> lambda{};
  double dist = 0;
};

// A bounding-volume hierarchy over triangles (vertex positions + index triples), built
// by median splits along the longest axis. Ties between equally near triangles go to the
// lower face index, so the answer does not depend on the traversal order.
class TriangleTree {
 public:
  TriangleTree(const std::vector<Eigen::Vector3d>& points, const std::vector<std::array<int, 3>>& tris);
  MeshPoint closest(const Eigen::Vector3d& p) const;

 private:
  struct Node {
    Eigen::Vector3d lo, hi;
    int begin = 0, end = 0;  // range in order_ (leaf) ...
    int left = -1, right = -1;
  };
  int build(int begin, int end);
  void search(int node, const Eigen::Vector3d& p, MeshPoint& best, double& best2) const;
  const std::vector<Eigen::Vector3d>& points_;
  const std::vector<std::array<int, 3>>& tris_;
  std::vector<int> order_;
  std::vector<Eigen::Vector3d> centroid_;
  std::vector<Node> nodes_;
};

// Brute force over all triangles: the reference for tests.
MeshPoint closest_brute_force(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& points,
                              const std::vector<std::array<int, 3>>& tris);

}  // namespace fest::feshape
