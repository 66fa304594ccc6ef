#include "reflectance/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace fest::reflectance {

void compute_vertex_normals(TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> acc(mesh.vertices.size(), Eigen::Vector3d::Zero());
  for (const auto& tri : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d& b = mesh.vertices[tri[1]];
    const Eigen::Vector3d& c = mesh.vertices[tri[2]];
    Eigen::Vector3d n = (b - a).cross(c - a);
    const double len = n.norm();
    if (!(len > 0)) continue;
    n /= len;
    const Eigen::Vector3d* p[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e1 = (*p[(k + 1) % 3] - *p[k]).normalized();
      const Eigen::Vector3d e2 = (*p[(k + 2) % 3] - *p[k]).normalized();
      const double angle = std::acos(std::clamp(e1.dot(e2), -1.0, 1.0));
      acc[tri[k]] += angle * n;
    }
  }
  mesh.normals.resize(mesh.vertices.size());
  for (std::size_t i = 0; i < acc.size(); ++i) {
    const double len = acc[i].norm();
    mesh.normals[i] = len > 0 ? Eigen::Vector3d(acc[i] / len) : Eigen::Vector3d::UnitZ();
  }
}

void bounding_sphere(const TriangleMesh& mesh, Eigen::Vector3d& centre, double& radius) {
  centre.setZero();
  radius = 0;
  if (mesh.vertices.empty()) return;
  Eigen::Vector3d lo = mesh.vertices[0], hi = lo;
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  centre = 0.5 * (lo + hi);
  for (const auto& v : mesh.vertices) radius = std::max(radius, (v - centre).norm());
}

double bbox_diagonal(const TriangleMesh& mesh) {
  if (mesh.vertices.empty()) return 0;
  Eigen::Vector3d lo = mesh.vertices[0], hi = lo;
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return (hi - lo).norm();
}

}  // namespace fest::reflectance
