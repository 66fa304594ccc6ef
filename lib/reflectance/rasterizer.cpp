#include "reflectance/rasterizer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/parallel_for.hpp"
#include "reflectance/triangle_scan.hpp"

namespace fest::reflectance {
namespace {

using scan::drawable;
using scan::project_vertices;
using scan::scan_triangle;
using scan::ScreenVertex;

}  // namespace

Fragments rasterize(const TriangleMesh& mesh, const PinholeCamera& camera, const RasterOptions& options) {
  Fragments f;
  f.width = camera.width;
  f.height = camera.height;
  const std::size_t n = static_cast<std::size_t>(f.width) * f.height;
  f.triangle.assign(n, -1);
  f.depth.assign(n, std::numeric_limits<float>::infinity());
  if (options.barycentrics) {
    f.b1.assign(n, 0.f);
    f.b2.assign(n, 0.f);
  }
  const std::vector<ScreenVertex> s = project_vertices(mesh, camera);
  // Depth is compared in double per band, then stored as float.
  parallel_bands(f.height, options.threads, [&](int y0, int y1) {
    std::vector<double> zbuf(static_cast<std::size_t>(y1 - y0) * f.width, std::numeric_limits<double>::infinity());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      const ScreenVertex &a = s[tri[0]], &b = s[tri[1]], &c = s[tri[2]];
      if (!drawable(a, b, c)) continue;
      scan_triangle(a, b, c, f.width, y0, y1, [&](int x, int y, double l0, double l1, double l2) {
        // Perspective-correct interpolation: 1/z is affine in screen space.
        const double q0 = l0 / a.z, q1 = l1 / b.z, q2 = l2 / c.z;
        const double inv_z = q0 + q1 + q2;
        const double z = 1.0 / inv_z;
        double& zb = zbuf[static_cast<std::size_t>(y - y0) * f.width + x];
        if (!(z < zb)) return;
        zb = z;
        const std::size_t i = f.index(x, y);
        f.triangle[i] = static_cast<std::int32_t>(t);
        f.depth[i] = static_cast<float>(z);
        if (options.barycentrics) {
          f.b1[i] = static_cast<float>(q1 * z);
          f.b2[i] = static_cast<float>(q2 * z);
        }
      });
    }
  });
  return f;
}

std::vector<std::uint8_t> rasterize_silhouette(const TriangleMesh& mesh, const PinholeCamera& camera, int threads) {
  std::vector<std::uint8_t> cover(static_cast<std::size_t>(camera.width) * camera.height, 0);
  const std::vector<ScreenVertex> s = project_vertices(mesh, camera);
  parallel_bands(camera.height, threads, [&](int y0, int y1) {
    for (const auto& tri : mesh.triangles) {
      const ScreenVertex &a = s[tri[0]], &b = s[tri[1]], &c = s[tri[2]];
      if (!drawable(a, b, c)) continue;
      scan::scan_spans(a, b, c, camera.width, y0, y1, [&](int y, int x0, int x1) {
        std::uint8_t* row = &cover[static_cast<std::size_t>(y) * camera.width];
        std::fill(row + x0, row + x1 + 1, std::uint8_t{1});
      });
    }
  });
  return cover;
}

std::vector<std::uint32_t> projected_pixel_counts(const TriangleMesh& mesh, const PinholeCamera& camera) {
  std::vector<std::uint32_t> count(mesh.triangles.size(), 0);
  const std::vector<ScreenVertex> s = project_vertices(mesh, camera);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const ScreenVertex &a = s[tri[0]], &b = s[tri[1]], &c = s[tri[2]];
    if (!drawable(a, b, c)) continue;
    scan::scan_spans(a, b, c, camera.width, 0, camera.height,
                     [&](int, int x0, int x1) { count[t] += static_cast<std::uint32_t>(x1 - x0 + 1); });
  }
  return count;
}

Eigen::Vector3d fragment_point(const TriangleMesh& mesh, const Fragments& f, std::size_t i) {
  const auto& tri = mesh.triangles[static_cast<std::size_t>(f.triangle[i])];
  const double b1 = f.b1[i], b2 = f.b2[i];
  return (1 - b1 - b2) * mesh.vertices[tri[0]] + b1 * mesh.vertices[tri[1]] + b2 * mesh.vertices[tri[2]];
}

Eigen::Vector3d fragment_normal(const TriangleMesh& mesh, const Fragments& f, std::size_t i) {
  const auto& tri = mesh.triangles[static_cast<std::size_t>(f.triangle[i])];
  const double b1 = f.b1[i], b2 = f.b2[i];
  const Eigen::Vector3d n = (1 - b1 - b2) * mesh.normals[tri[0]] + b1 * mesh.normals[tri[1]] + b2 * mesh.normals[tri[2]];
  const double len = n.norm();
  return len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::UnitZ();
}

bool ShadowMap::lit(const Eigen::Vector3d& world_point) const {
  const Eigen::Vector3d xc = view.to_camera(world_point);
  if (xc.z() <= 0) return true;
  const Eigen::Vector2d p = view.project_camera(xc);
  const int x0 = static_cast<int>(std::floor(p.x())), y0 = static_cast<int>(std::floor(p.y()));
  double farthest = -1;
  bool inside = false;
  for (int dy = 0; dy <= 1; ++dy)
    for (int dx = 0; dx <= 1; ++dx) {
      const int x = x0 + dx, y = y0 + dy;
      if (x < 0 || y < 0 || x >= fragments.width || y >= fragments.height) return true;
      inside = true;
      farthest = std::max(farthest, static_cast<double>(fragments.depth[fragments.index(x, y)]));
    }
  return !inside || xc.z() <= farthest + eps;
}

ShadowMap make_shadow_map(const TriangleMesh& mesh, const Eigen::Vector3d& light_position, int resolution, double eps,
                          int threads) {
  Eigen::Vector3d centre;
  double radius = 0;
  bounding_sphere(mesh, centre, radius);
  const double d = (centre - light_position).norm();
  if (!(d > radius * 1.0001))
    throw bad_input("the light at ({}, {}, {}) lies inside the object's bounding sphere (radius {})", light_position.x(),
                    light_position.y(), light_position.z(), radius);
  ShadowMap map;
  map.eps = eps;
  PinholeCamera& v = map.view;
  v.width = v.height = resolution;
  v.R = look_at_rotation(light_position, centre, std::abs((centre - light_position).normalized().z()) > 0.9
                                                      ? Eigen::Vector3d::UnitX()
                                                      : Eigen::Vector3d::UnitZ());
  v.t = -v.R * light_position;
  // The bounding sphere's cone has half-angle asin(r/d); one texel of margin on each side.
  const double half = std::asin(radius / d);
  v.fx = v.fy = (0.5 * resolution - 1) / std::tan(half);
  v.cx = v.cy = 0.5 * (resolution - 1);
  RasterOptions o;
  o.threads = threads;
  o.barycentrics = false;
  map.fragments = rasterize(mesh, v, o);
  return map;
}

}  // namespace fest::reflectance
