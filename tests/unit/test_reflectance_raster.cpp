// The renderer against closed forms: a plane's radiance under a point light, a sphere's
// silhouette area, a shadow cast by a known occluder, perspective-correct surface points.

#include <cmath>

#include <gtest/gtest.h>

#include "reflectance/rasterizer.hpp"
#include "reflectance/render.hpp"

#include "test_reflectance_helpers.hpp"

namespace {

using namespace fest::reflectance;

using fest::test::plane;

// A camera at `eye` looking at the origin.
PinholeCamera camera_at(const Eigen::Vector3d& eye, int w, int h, double f, const Eigen::Vector3d& up) {
  PinholeCamera c;
  c.width = w;
  c.height = h;
  c.fx = c.fy = f;
  c.cx = 0.5 * (w - 1);
  c.cy = 0.5 * (h - 1);
  c.R = look_at_rotation(eye, Eigen::Vector3d::Zero(), up);
  c.t = -c.R * eye;
  return c;
}

// The shared octahedron sphere with normals (enough for silhouettes and shading).
TriangleMesh unit_icosphere(int level) {
  TriangleMesh m = fest::test::octahedron_sphere(level);
  compute_vertex_normals(m);
  return m;
}

SurfaceMaterials lambertian(std::size_t triangles, const Rgb& rho) {
  SurfaceMaterials s;
  LafortuneBrdf b;
  b.rho_d = rho;
  s.brdfs = {b};
  s.triangle_material.assign(triangles, 0);
  return s;
}

}  // namespace

TEST(Raster, PlaneRadianceUnderAPointLightIsClosedForm) {
  const TriangleMesh m = plane(1.0, 0.0, 8);
  const PinholeCamera cam = camera_at({0.3, -0.4, 3.0}, 160, 120, 150, Eigen::Vector3d::UnitY());
  PointLight light;
  light.position = Eigen::Vector3d(-0.5, 0.7, 1.5);
  light.intensity = Rgb(2.0, 3.0, 4.0);
  const Rgb rho(0.5, 0.4, 0.3);
  RenderOptions o;
  o.shadows = true;
  const Rendering r = render(m, lambertian(m.triangles.size(), rho), cam, light, o);
  int checked = 0;
  for (int y = 0; y < cam.height; y += 7)
    for (int x = 0; x < cam.width; x += 7) {
      // The pixel ray meets z = 0 at p; L = I rho / pi * cos(theta_i) / d^2.
      const Eigen::Vector3d dir = cam.ray_direction(x, y), c = cam.centre();
      const Eigen::Vector3d p = c + dir * (-c.z() / dir.z());
      if (std::abs(p.x()) > 0.999 || std::abs(p.y()) > 0.999) {
        if (std::abs(p.x()) > 1.001 || std::abs(p.y()) > 1.001) {
          EXPECT_EQ(r.mask.at<std::uint8_t>(y, x), 0);
        }
        continue;
      }
      ASSERT_EQ(r.mask.at<std::uint8_t>(y, x), 255) << x << "," << y;
      const Eigen::Vector3d to_light = light.position - p;
      const double cos_i = to_light.z() / to_light.norm();
      for (int k = 0; k < 3; ++k) {
        const double expected = light.intensity[k] * rho[k] / M_PI * cos_i / to_light.squaredNorm();
        EXPECT_NEAR(r.radiance.at<cv::Vec3f>(y, x)[k], expected, 2e-6 * expected + 1e-7);
      }
      ++checked;
    }
  EXPECT_GT(checked, 150);
}

TEST(Raster, SphereSilhouetteAreaMatchesPerspectiveDisc) {
  // A unit sphere at distance D on the optical axis projects to a disc of radius
  // f r / sqrt(D^2 - r^2).
  const TriangleMesh m = unit_icosphere(6);
  const double D = 4, f = 300;
  const PinholeCamera cam = camera_at({0, 0, D}, 400, 400, f, Eigen::Vector3d::UnitY());
  const std::vector<std::uint8_t> s = rasterize_silhouette(m, cam, 2);
  double count = 0;
  for (std::uint8_t v : s) count += v;
  const double rho = f / std::sqrt(D * D - 1);
  EXPECT_NEAR(count / (M_PI * rho * rho), 1.0, 0.005);
}

TEST(Raster, PerspectiveCorrectPointsReprojectToThePixelCentre) {
  const TriangleMesh m = unit_icosphere(3);
  const PinholeCamera cam = camera_at({1.0, -2.5, 1.5}, 200, 150, 180, Eigen::Vector3d::UnitZ());
  const Fragments f = rasterize(m, cam);
  int n = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const std::size_t i = f.index(x, y);
      if (f.triangle[i] < 0) continue;
      const Eigen::Vector2d px = cam.project_camera(cam.to_camera(fragment_point(m, f, i)));
      EXPECT_NEAR(px.x(), x, 1e-3);
      EXPECT_NEAR(px.y(), y, 1e-3);
      EXPECT_NEAR(cam.to_camera(fragment_point(m, f, i)).z(), f.depth[i], 1e-5);
      ++n;
    }
  EXPECT_GT(n, 5000);
}

TEST(Raster, OccluderCastsItsShadowWhereTheLightRaysSay) {
  // A small square at height 0.5 above a big plane, light straight above at height 4:
  // the shadow is the square scaled by 4 / (4 - 0.5) around the origin.
  TriangleMesh m = plane(2.0, 0.0, 4);
  const TriangleMesh occ = plane(0.3, 0.5, 1);
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), occ.vertices.begin(), occ.vertices.end());
  m.normals.insert(m.normals.end(), occ.normals.begin(), occ.normals.end());
  for (auto t : occ.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  const ShadowMap sm = make_shadow_map(m, Eigen::Vector3d(0, 0, 4), 1024, 0.01, 2);
  const double edge = 0.3 * 4 / 3.5;
  for (double x = -1.5; x <= 1.5; x += 0.05)
    for (double y = -1.5; y <= 1.5; y += 0.05) {
      const double e = std::max(std::abs(x), std::abs(y));
      if (std::abs(e - edge) < 0.02) continue;  // one texel of softness at the edge
      EXPECT_EQ(sm.lit(Eigen::Vector3d(x, y, 0)), e > edge) << x << "," << y;
    }
  EXPECT_TRUE(sm.lit(Eigen::Vector3d(0, 0, 0.5)));  // the occluder lights itself
}

TEST(Raster, SameImageForEveryThreadCount) {
  const TriangleMesh m = unit_icosphere(4);
  const PinholeCamera cam = camera_at({0.5, -3, 1}, 123, 97, 90, Eigen::Vector3d::UnitZ());
  PointLight light;
  light.position = Eigen::Vector3d(2, -2, 2);
  RenderOptions a, b;
  a.threads = 1;
  b.threads = 3;
  const SurfaceMaterials mat = lambertian(m.triangles.size(), Rgb(0.5, 0.5, 0.5));
  const Rendering r1 = render(m, mat, cam, light, a), r3 = render(m, mat, cam, light, b);
  EXPECT_EQ(cv::norm(r1.radiance, r3.radiance, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(r1.mask, r3.mask, cv::NORM_INF), 0.0);
}

TEST(Raster, EnvironmentIrradianceOfAConstantSkyIsPiTimesRadiance) {
  EnvironmentMap env;
  env.width = 64;
  env.height = 32;
  env.rgb.assign(64 * 32 * 3, 2.0f);
  const IrradianceSH sh = project_irradiance(env);
  const Eigen::Vector3d e = sh.irradiance(Eigen::Vector3d(0.3, -0.4, 0.866).normalized());
  EXPECT_NEAR(e[0], 2 * M_PI, 2 * M_PI * 2e-3);
  EXPECT_NEAR(env.radiance(Eigen::Vector3d(0, 0, 1))[1], 2.0, 1e-6);
}
