#pragma once
// Rendering of a mesh made of Lafortune materials under one point light (docs/brdffit.md
// §1, §6): for every pixel the visible surface point p with its interpolated shading
// normal n, u towards the light, v towards the camera, and
//
//   L = I f_r(u, v) u_z / d^2      (d = |q - p|; 0 when shadowed or when u_z or v_z <= 0)
//
// plus, optionally, diffuse light from an environment map (rho_d / pi times its
// irradiance at n, no visibility: an ambient term the point-light model does not explain)
// and the environment map as the background. Output is linear radiance (RGB float) and
// the object's mask. Deterministic; parallel over bands of rows.

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "reflectance/camera.hpp"
#include "reflectance/environment.hpp"
#include "reflectance/lafortune.hpp"
#include "reflectance/rasterizer.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::reflectance {

struct PointLight {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Rgb intensity = Rgb::Ones();
};

// Which BRDF each surface point has: either one material per triangle, or per-vertex
// blending weights over all materials (interpolated barycentrically; f = sum_j w_j f_j).
struct SurfaceMaterials {
  std::vector<LafortuneBrdf> brdfs;
  std::vector<std::uint16_t> triangle_material;  // per triangle; used when vertex_weights is empty
  std::vector<float> vertex_weights;             // vertices x brdfs, row-major (blends)

  // f_r at a point of triangle `tri` with barycentrics (b1, b2); directions in the local frame.
  Rgb evaluate(std::size_t tri, const std::array<std::uint32_t, 3>& corners, double b1, double b2,
               const Eigen::Vector3d& u_local, const Eigen::Vector3d& v_local) const;
  // The diffuse albedo there (for environment light).
  Rgb rho_d(std::size_t tri, const std::array<std::uint32_t, 3>& corners, double b1, double b2) const;
};

struct RenderOptions {
  int threads = 1;
  bool shadows = true;
  int shadow_resolution = 2048;
  double shadow_eps = 0;                        // world units; 0: 0.2 % of the bbox diagonal
  const EnvironmentMap* background = nullptr;   // seen where no surface covers a pixel
  const IrradianceSH* ambient = nullptr;        // diffuse environment light on the surface
  double ambient_scale = 1;
};

struct Rendering {
  cv::Mat radiance;  // CV_32FC3, RGB order, linear
  cv::Mat mask;      // CV_8U, 255 where the object covers the pixel centre
};

// Throws fest::Error (bad_input) for material tables that do not fit the mesh.
Rendering render(const TriangleMesh& mesh, const SurfaceMaterials& materials, const PinholeCamera& camera,
                 const PointLight& light, const RenderOptions& options = {});

// The radiance a point light sends from a surface point towards a camera centre (the
// shading of one pixel, no visibility): I f_r(u, v) u_z / d^2.
Rgb shade_point(const SurfaceMaterials& materials, const TriangleMesh& mesh, std::size_t tri, double b1, double b2,
                const Eigen::Vector3d& p, const Eigen::Vector3d& n, const Eigen::Vector3d& eye, const PointLight& light);

}  // namespace fest::reflectance
