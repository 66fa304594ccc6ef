#include "softobj/mesh_measures.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "softobj/shrinkwrap.hpp"

namespace fest::softobj {

namespace {
Eigen::Vector3d P(const TriMesh& m, TriMesh::VertexHandle v) {
  const auto& p = m.point(v);
  return {p[0], p[1], p[2]};
}
}  // namespace

MeshMeasures measure(const TriMesh& m) {
  MeshMeasures r;
  r.vertices = m.n_vertices();
  r.triangles = m.n_faces();
  r.euler_characteristic = static_cast<int>(m.n_vertices()) - static_cast<int>(m.n_edges()) + static_cast<int>(m.n_faces());
  r.closed = true;
  for (auto h : m.halfedges())
    if (m.is_boundary(h)) r.closed = false;
  for (auto f : m.faces()) {
    std::array<Eigen::Vector3d, 3> q;
    int k = 0;
    for (auto v : m.fv_range(f)) q[k++] = P(m, v);
    r.volume += q[0].dot(q[1].cross(q[2])) / 6.0;  // divergence theorem, tetrahedra to the origin
    r.area += 0.5 * (q[1] - q[0]).cross(q[2] - q[0]).norm();
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d a = q[(i + 1) % 3] - q[i], b = q[(i + 2) % 3] - q[i];
      const double ang = std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / M_PI;
      r.min_angle_deg = std::min(r.min_angle_deg, ang);
    }
  }
  const bool normals = m.has_vertex_normals();
  for (auto e : m.edges()) {
    const auto h = m.halfedge_handle(e, 0);
    const auto a = m.from_vertex_handle(h), b = m.to_vertex_handle(h);
    r.max_edge = std::max(r.max_edge, (P(m, a) - P(m, b)).norm());
    if (normals) {
      const auto na = m.normal(a), nb = m.normal(b);
      const double c = std::clamp(na | nb, -1.0, 1.0);
      r.max_normal_angle_deg = std::max(r.max_normal_angle_deg, std::acos(c) * 180 / M_PI);
    }
  }
  return r;
}

double max_iso_error(const Field& field, const TriMesh& m, double iso) {
  double e = 0;
  for (auto v : m.vertices()) e = std::max(e, std::abs(field.value(P(m, v)) - iso) / iso);
  return e;
}

double max_centroid_deviation(const Field& field, const TriMesh& m, double iso) {
  double worst = 0;
  for (auto f : m.faces()) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (auto v : m.fv_range(f)) c += P(m, v) / 3.0;
    Eigen::Vector3d r = c;
    project_to_iso(field, r, iso, 1e-12, 0);
    worst = std::max(worst, (r - c).norm());
  }
  return worst;
}

double max_sampled_deviation(const Field& field, const TriMesh& m, double iso, int order) {
  double worst = 0;
  for (auto f : m.faces()) {
    std::array<Eigen::Vector3d, 3> q;
    int k = 0;
    for (auto v : m.fv_range(f)) q[k++] = P(m, v);
    for (int i = 0; i <= order; ++i)
      for (int j = 0; i + j <= order; ++j) {
        const int l = order - i - j;
        if (i == order || j == order || l == order) continue;  // the vertices lie on the surface
        const Eigen::Vector3d c = (i * q[0] + j * q[1] + l * q[2]) / order;
        Eigen::Vector3d r = c;
        project_to_iso(field, r, iso, 1e-12, 0);
        worst = std::max(worst, (r - c).norm());
      }
  }
  return worst;
}

}  // namespace fest::softobj
