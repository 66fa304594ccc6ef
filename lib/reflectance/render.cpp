#include "reflectance/render.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/parallel_for.hpp"

namespace fest::reflectance {

Rgb SurfaceMaterials::evaluate(std::size_t tri, const std::array<std::uint32_t, 3>& c, double b1, double b2,
                               const Eigen::Vector3d& u, const Eigen::Vector3d& v) const {
  if (vertex_weights.empty()) return reflectance::evaluate(brdfs[triangle_material[tri]], u, v);
  const std::size_t m = brdfs.size();
  Rgb f = Rgb::Zero();
  const double b0 = 1 - b1 - b2;
  for (std::size_t j = 0; j < m; ++j) {
    const double w = b0 * vertex_weights[c[0] * m + j] + b1 * vertex_weights[c[1] * m + j] +
                     b2 * vertex_weights[c[2] * m + j];
    if (w != 0) f += w * reflectance::evaluate(brdfs[j], u, v);
  }
  return f;
}

Rgb SurfaceMaterials::rho_d(std::size_t tri, const std::array<std::uint32_t, 3>& c, double b1, double b2) const {
  if (vertex_weights.empty()) return brdfs[triangle_material[tri]].rho_d;
  const std::size_t m = brdfs.size();
  Rgb r = Rgb::Zero();
  const double b0 = 1 - b1 - b2;
  for (std::size_t j = 0; j < m; ++j)
    r += (b0 * vertex_weights[c[0] * m + j] + b1 * vertex_weights[c[1] * m + j] + b2 * vertex_weights[c[2] * m + j]) *
         brdfs[j].rho_d;
  return r;
}

Rgb shade_point(const SurfaceMaterials& materials, const TriangleMesh& mesh, std::size_t tri, double b1, double b2,
                const Eigen::Vector3d& p, const Eigen::Vector3d& n, const Eigen::Vector3d& eye, const PointLight& light) {
  const Eigen::Vector3d to_light = light.position - p;
  const double d2 = to_light.squaredNorm();
  const Eigen::Matrix3d frame = local_frame(n);
  const Eigen::Vector3d u = frame.transpose() * (to_light / std::sqrt(d2));
  const Eigen::Vector3d v = frame.transpose() * (eye - p).normalized();
  if (u.z() <= 0 || v.z() <= 0) return Rgb::Zero();
  const Rgb f = materials.evaluate(tri, mesh.triangles[tri], b1, b2, u, v);
  return light.intensity.cwiseProduct(f) * (u.z() / d2);
}

namespace {

void check_materials(const TriangleMesh& mesh, const SurfaceMaterials& m) {
  if (m.brdfs.empty()) throw bad_input("no materials given");
  if (m.vertex_weights.empty()) {
    if (m.triangle_material.size() != mesh.triangles.size())
      throw bad_input("{} material ids for {} triangles", m.triangle_material.size(), mesh.triangles.size());
    for (std::uint16_t id : m.triangle_material)
      if (id >= m.brdfs.size()) throw bad_input("material id {} but only {} materials", id, m.brdfs.size());
  } else if (m.vertex_weights.size() != mesh.vertices.size() * m.brdfs.size()) {
    throw bad_input("{} vertex weights for {} vertices x {} materials", m.vertex_weights.size(), mesh.vertices.size(),
                    m.brdfs.size());
  }
  if (mesh.normals.size() != mesh.vertices.size()) throw bad_input("the mesh has no vertex normals");
}

}  // namespace

Rendering render(const TriangleMesh& mesh, const SurfaceMaterials& materials, const PinholeCamera& camera,
                 const PointLight& light, const RenderOptions& options) {
  check_materials(mesh, materials);
  RasterOptions ro;
  ro.threads = options.threads;
  const Fragments f = rasterize(mesh, camera, ro);
  ShadowMap shadow;
  if (options.shadows) {
    const double eps = options.shadow_eps > 0 ? options.shadow_eps : 0.002 * bbox_diagonal(mesh);
    shadow = make_shadow_map(mesh, light.position, options.shadow_resolution, eps, options.threads);
  }
  Rendering out;
  out.radiance = cv::Mat(camera.height, camera.width, CV_32FC3, cv::Scalar::all(0));
  out.mask = cv::Mat(camera.height, camera.width, CV_8U, cv::Scalar(0));
  const Eigen::Vector3d eye = camera.centre();
  parallel_bands(camera.height, options.threads, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
      auto* rad = out.radiance.ptr<cv::Vec3f>(y);
      auto* msk = out.mask.ptr<std::uint8_t>(y);
      for (int x = 0; x < camera.width; ++x) {
        const std::size_t i = f.index(x, y);
        Rgb L = Rgb::Zero();
        if (f.triangle[i] < 0) {
          if (options.background) L = options.background->radiance(camera.ray_direction(x, y));
        } else {
          msk[x] = 255;
          const std::size_t tri = static_cast<std::size_t>(f.triangle[i]);
          const Eigen::Vector3d p = fragment_point(mesh, f, i);
          const Eigen::Vector3d n = fragment_normal(mesh, f, i);
          if (!options.shadows || shadow.lit(p)) L = shade_point(materials, mesh, tri, f.b1[i], f.b2[i], p, n, eye, light);
          if (options.ambient && (eye - p).dot(n) > 0)
            L += options.ambient_scale / M_PI *
                 materials.rho_d(tri, mesh.triangles[tri], f.b1[i], f.b2[i]).cwiseProduct(options.ambient->irradiance(n));
        }
        rad[x] = cv::Vec3f(static_cast<float>(L[0]), static_cast<float>(L[1]), static_cast<float>(L[2]));
      }
    }
  });
  return out;
}

}  // namespace fest::reflectance
