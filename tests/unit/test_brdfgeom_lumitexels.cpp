// Lumitexel generation on scenes with known answers (docs/brdffit.md §7): one
// lumitexel per covered pixel, exact reprojection, r = f u_z, sample counts, occlusion and
// shadows, and the "no lumitexel with enough samples" error.

#include <cmath>

#include <gtest/gtest.h>

#include "brdffit/lumitexel_builder.hpp"
#include "brdffit/synthetic_scene.hpp"
#include "core/error.hpp"
#include "reflectance/rasterizer.hpp"
#include "reflectance/render.hpp"

#include "test_reflectance_helpers.hpp"

namespace {

using namespace fest;
using namespace fest::brdffit;
using namespace fest::reflectance;

// The square [-s, s]^2 at z = 0 in 2 n^2 triangles.
TriangleMesh plane(double s, int n) { return fest::test::plane(s, 0.0, n); }

ImageView view_from(const Eigen::Vector3d& eye, const Eigen::Vector3d& light, int w = 240, int h = 200) {
  ImageView v;
  v.camera.width = w;
  v.camera.height = h;
  v.camera.fx = v.camera.fy = 140;
  v.camera.cx = 0.5 * (w - 1);
  v.camera.cy = 0.5 * (h - 1);
  v.camera.R = look_at_rotation(eye, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitY());
  v.camera.t = -v.camera.R * eye;
  v.light.position = light;
  v.light.intensity = Rgb(1.5, 2.0, 2.5);
  return v;
}

SurfaceMaterials single(std::size_t triangles, const LafortuneBrdf& b) {
  SurfaceMaterials s;
  s.brdfs = {b};
  s.triangle_material.assign(triangles, 0);
  return s;
}

// Renders every view with the renderer itself: the photographs of a perfect capture.
ImageLoader renderer_loader(const TriangleMesh& m, const SurfaceMaterials& mat, const std::vector<ImageView>& views) {
  return [&m, mat, views](std::size_t k) {
    const Rendering r = render(m, mat, views[k].camera, views[k].light);
    return ImagePixels{r.radiance, r.mask, cv::Mat()};
  };
}

}  // namespace

TEST(Lumitexels, OnePerCoveredPixelAndExactReprojection) {
  const TriangleMesh m = plane(0.5, 6);
  LafortuneBrdf b;
  b.rho_d = Rgb(0.6, 0.5, 0.4);
  const std::vector<ImageView> views = {view_from({0.1, 0.2, 2.0}, {0.5, -0.3, 1.5})};
  LumitexelOptions o;
  o.min_samples = 1;
  LumitexelReport rep;
  const LumitexelSet set = build_lumitexels(m, views, renderer_loader(m, single(m.triangles.size(), b), views), o, &rep);
  const std::vector<std::uint8_t> cover = rasterize_silhouette(m, views[0].camera);
  std::size_t covered = 0;
  for (std::uint8_t c : cover) covered += c;
  EXPECT_EQ(rep.candidates, covered);
  // Border pixels lose their sample (a bilinear tap outside the mask): a thin rim.
  EXPECT_GT(static_cast<double>(set.lumitexels.size()), 0.95 * static_cast<double>(covered));
  EXPECT_EQ(rep.dropped, covered - set.lumitexels.size());
  double worst = 0, worst_r = 0;
  for (const Lumitexel& l : set.lumitexels) {
    const Eigen::Vector2d px = views[0].camera.project_camera(views[0].camera.to_camera(l.p.cast<double>()));
    worst = std::max(worst, (px - l.home_pixel.cast<double>()).norm());
    ASSERT_EQ(l.count, 1);
    const Sample& s = set.samples[l.first_sample];
    const double uz = s.u_world.cast<double>().dot(Eigen::Vector3d::UnitZ());
    for (int c = 0; c < 3; ++c) worst_r = std::max(worst_r, std::abs(s.r[c] - b.rho_d[c] / M_PI * uz) / (b.rho_d[c] / M_PI * uz));
  }
  EXPECT_LT(worst, 0.01);  // pixels
  // r = L d^2 / I = f u_z; bilinear resampling of a smooth image: small relative error.
  EXPECT_LT(worst_r, 2e-3);
}

TEST(Lumitexels, EveryCameraThatSeesThePlaneGivesOneSample) {
  const TriangleMesh m = plane(0.5, 4);
  LafortuneBrdf b;
  b.rho_d = Rgb(0.5, 0.5, 0.5);
  const std::vector<ImageView> views = {view_from({0.0, 0.0, 2.5}, {0.5, 0.5, 2}),
                                        view_from({0.8, 0.0, 2.2}, {-0.5, 0.5, 2}),
                                        view_from({-0.6, 0.6, 2.2}, {0.0, -0.8, 2})};
  LumitexelOptions o;
  const LumitexelSet set = build_lumitexels(m, views, renderer_loader(m, single(m.triangles.size(), b), views), o, nullptr);
  std::size_t three = 0;
  for (const Lumitexel& l : set.lumitexels) {
    three += l.count == 3;
    EXPECT_LE(l.count, 3);
    // Samples in image order, one per image.
    for (std::uint16_t k = 1; k < l.count; ++k)
      EXPECT_LT(set.samples[l.first_sample + k - 1].image, set.samples[l.first_sample + k].image);
  }
  // Points near the plane's outline in another image lose that sample (bilinear taps
  // outside its mask): the rim is a few per cent.
  EXPECT_GT(static_cast<double>(three), 0.9 * static_cast<double>(set.lumitexels.size()));
}

TEST(Lumitexels, OccludedAndShadowedSamplesAreLeftOut) {
  // Two spheres: B (radius 1 at the origin) and A (radius 0.3) between B and the light.
  TriangleMesh m = icosphere(4, 1.0);
  TriangleMesh a = icosphere(3, 0.3);
  const Eigen::Vector3d a_centre(0, 0, 1.8), light(0, 0, 4.0);
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    m.vertices.push_back(a.vertices[i] + a_centre);
    m.normals.push_back(a.normals[i]);
  }
  for (auto t : a.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  LafortuneBrdf b;
  b.rho_d = Rgb(0.5, 0.5, 0.5);
  std::vector<ImageView> views;
  for (int k = 0; k < 6; ++k) {
    const double phi = 2 * M_PI * k / 6;
    views.push_back(view_from({3.5 * std::cos(phi), 3.5 * std::sin(phi), 2.5}, light, 160, 160));
  }
  LumitexelOptions o;
  o.min_samples = 1;
  LumitexelReport rep;
  const LumitexelSet set = build_lumitexels(m, views, renderer_loader(m, single(m.triangles.size(), b), views), o, &rep);
  EXPECT_GT(rep.rejected_shadowed, 0u);
  EXPECT_GT(rep.rejected_occluded, 0u);
  // The umbra of A on B: the cone from the light around A's centre, half-angle asin(0.3/2.2).
  const double half = std::asin(0.3 / (light - a_centre).norm());
  std::size_t inside_checked = 0, outside_lit = 0;
  for (const Lumitexel& l : set.lumitexels) {
    if (l.triangle >= base) continue;  // points on A
    const Eigen::Vector3d p = l.p.cast<double>();
    const double angle = std::acos((p - light).normalized().dot((a_centre - light).normalized()));
    if (angle < half * 0.9) {
      ++inside_checked;
      ADD_FAILURE() << "a point in A's umbra has " << l.count << " samples";
    } else if (angle > half * 1.1 && (light - p).normalized().dot(l.n.cast<double>()) > 0.2) {
      outside_lit += l.count > 0;
    }
  }
  EXPECT_EQ(inside_checked, 0u);
  EXPECT_GT(outside_lit, 100u);
}

TEST(Lumitexels, NoLumitexelWithEnoughSamplesIsBadInput) {
  const TriangleMesh m = plane(0.5, 2);
  LafortuneBrdf b;
  b.rho_d = Rgb(0.5, 0.5, 0.5);
  const std::vector<ImageView> views = {view_from({0, 0, 2}, {0, 0.5, 2})};
  LumitexelOptions o;
  o.min_samples = 2;  // one image: at most one sample each
  try {
    build_lumitexels(m, views, renderer_loader(m, single(m.triangles.size(), b), views), o, nullptr);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input);
    EXPECT_NE(std::string(e.what()).find("no lumitexel has >= 2 samples"), std::string::npos) << e.what();
  }
}

TEST(Lumitexels, ImageSizeMustMatchItsCamera) {
  const TriangleMesh m = plane(0.5, 2);
  const std::vector<ImageView> views = {view_from({0, 0, 2}, {0, 0.5, 2})};
  auto load = [](std::size_t) { return ImagePixels{cv::Mat(10, 10, CV_32FC3, cv::Scalar::all(0)), cv::Mat(), cv::Mat()}; };
  EXPECT_THROW(build_lumitexels(m, views, load, LumitexelOptions{}, nullptr), Error);
}
