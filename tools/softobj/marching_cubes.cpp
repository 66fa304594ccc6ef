#include "marching_cubes.hpp"

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "isosurface/marching_cubes.hpp"
#include "softobj/shrinkwrap.hpp"

namespace fest::softobj_tool {

TriMesh marching_cubes(const softobj::Field& field, double iso, double rho, double h, std::size_t max_vertices,
                       std::size_t* dropped) {
  const auto& c = field.skeleton();
  Eigen::Vector3d lo0 = Eigen::Vector3d::Constant(1e300), hi0 = -lo0;
  for (const auto& t : c.terms)
    for (const auto& v : t.v) lo0 = lo0.cwiseMin(v), hi0 = hi0.cwiseMax(v);
  // fest's exact marching cubes (lib/isosurface, docs/isosurf.md "Exact mode") on float
  // samples: the vertices are projected onto the surface of the field itself below, so
  // the samples' precision only places the starting points.
  // The box grows by rho + 2h; overlapping primitives (a skeleton folding over itself)
  // push the surface further out, so the box grows until no sample on its faces reaches
  // the iso value (an open mesh otherwise).
  volume_pyramid::ScalarGrid grid;
  for (double grow = rho + 2 * h;; grow *= 1.5) {
    Eigen::Vector3d lo = lo0.array() - grow, hi = hi0.array() + grow;
    int n[3];
    double cells = 1;
    for (int k = 0; k < 3; ++k) n[k] = static_cast<int>(std::ceil((hi[k] - lo[k]) / h)) + 1, cells *= n[k];
    if (cells > 4e8) throw runtime_failure("a grid of {} x {} x {} samples is too large", n[0], n[1], n[2]);
    grid.dims = {std::size_t(n[0]), std::size_t(n[1]), std::size_t(n[2])};
    grid.origin = {lo.x(), lo.y(), lo.z()};
    grid.axes = {h, 0, 0, 0, h, 0, 0, 0, h};
    grid.values.resize(static_cast<std::size_t>(cells));
    std::size_t id = 0;
    bool boundary_inside = false;
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) {
          const double v = field.value(lo + h * Eigen::Vector3d(x, y, z));
          grid.values[id++] = static_cast<float>(v);
          if (v >= iso && (x == 0 || y == 0 || z == 0 || x == n[0] - 1 || y == n[1] - 1 || z == n[2] - 1))
            boundary_inside = true;
        }
    if (!boundary_inside) break;
  }
  const isosurface::Surface out = isosurface::extract_isosurface(grid, static_cast<float>(iso), {}, nullptr);
  if (out.vertices() > max_vertices) throw runtime_failure("more than {} vertices (the vertex limit)", max_vertices);
  TriMesh m;
  m.request_vertex_normals();
  std::vector<TriMesh::VertexHandle> vh;
  for (std::size_t i = 0; i < out.vertices(); ++i) {
    Eigen::Vector3d r(out.xyz[3 * i], out.xyz[3 * i + 1], out.xyz[3 * i + 2]);
    softobj::project_to_iso(field, r, iso, 1e-12, h);
    vh.push_back(m.add_vertex(TriMesh::Point(r.x(), r.y(), r.z())));
    const Eigen::Vector3d g = -field.eval(r).grad.normalized();
    m.set_normal(vh.back(), TriMesh::Normal(g.x(), g.y(), g.z()));
  }
  const std::vector<std::array<std::uint32_t, 3>>& tris = out.triangles;
  // Orient outward: the field decreases outwards, so a face normal should oppose grad f.
  double s = 0;
  for (const auto& t : tris) {
    const auto a = m.point(vh[t[0]]), b = m.point(vh[t[1]]), cc = m.point(vh[t[2]]);
    s += ((b - a) % (cc - a)) | m.normal(vh[t[0]]);
  }
  std::size_t lost = 0;
  for (const auto& t : tris) {
    const auto f = s >= 0 ? m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]) : m.add_face(vh[t[0]], vh[t[2]], vh[t[1]]);
    if (!f.is_valid()) ++lost;
  }
  if (dropped) *dropped = lost;
  return m;
}

}  // namespace fest::softobj_tool
