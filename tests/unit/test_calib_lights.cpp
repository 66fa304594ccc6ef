// Light position from chrome spheres (docs/capture.md §6): rays built from exact
// geometry meet at the light; spheres rendered with a highlight from a light about
// 0.5 m away give its position within 1 mm.

#include <gtest/gtest.h>

#include "calib_scenes.hpp"
#include "capture/calib_lights.hpp"
#include "capture/calib_synth.hpp"
#include "expect_error.hpp"

namespace {

using namespace fest;
using namespace fest::capture;

TEST(CalibLights, TriangulatesExactRays) {
  const cv::Vec3d q(10, -20, 300);
  std::vector<SphereRay> rays;
  for (const cv::Vec3d& o : {cv::Vec3d(0, 0, 500), cv::Vec3d(100, 0, 550), cv::Vec3d(-50, 80, 520)})
    rays.push_back(SphereRay{o, o, cv::normalize(q - o)});
  const LightFit fit = triangulate_light(rays);
  EXPECT_LT(cv::norm(fit.position - q), 1e-9);
  EXPECT_LT(fit.residual_rms_mm, 1e-9);
}

TEST(CalibLights, RefusesParallelOrSingleRays) {
  const SphereRay a{{0, 0, 0}, {0, 0, 500}, {0, 0, -1}}, b{{0, 0, 0}, {10, 0, 500}, {0, 0, -1}};
  test::expect_bad_input([&] { triangulate_light({a}); }, "at least 2");
  test::expect_bad_input([&] { triangulate_light({a, b}); }, "parallel");
}

TEST(CalibLights, MirrorPointReflectsTowardTheLight) {
  const test::SphereScene scene;
  for (const Sphere& s : scene.spheres) {
    const cv::Vec3d h = mirror_point(s, scene.light);
    const cv::Vec3d n = (h - s.centre) / s.radius, v = cv::normalize(h);
    const cv::Vec3d r = v - 2 * v.dot(n) * n;
    EXPECT_NEAR(r.dot(cv::normalize(scene.light - h)), 1.0, 1e-12);
  }
}

// The exact image of a sphere: its outline is where the tangent cone's rays land, its
// highlight where the mirror point does. sphere_ray must give back the centre and a ray
// through the light, through lens distortion too.
TEST(CalibLights, ExactOutlineAndHighlightGiveExactRay) {
  const test::SphereScene scene;
  const Intrinsics cam = test::camera(1600, 1280, 960, -0.05, 0.01);
  for (const Sphere& sp : scene.spheres) {
    const double d = cv::norm(sp.centre), sin_a = sp.radius / d, cos_a = std::sqrt(1 - sin_a * sin_a);
    const cv::Vec3d w = sp.centre / d;
    const cv::Vec3d u = cv::normalize(w.cross(cv::Vec3d(0, 1, 0))), v = w.cross(u);
    std::vector<cv::Point3d> points;
    for (int i = 0; i < 360; ++i) {
      const double phi = 2 * test::kPi * i / 360;
      const cv::Vec3d r = cos_a * w + sin_a * (std::cos(phi) * u + std::sin(phi) * v);
      points.emplace_back(r[0], r[1], r[2]);
    }
    const cv::Vec3d h = mirror_point(sp, scene.light);
    points.emplace_back(h[0], h[1], h[2]);
    std::vector<cv::Point2d> pixels;
    cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cv::Mat(cam.K), cv::Mat(cam.dist), pixels);
    SphereImage image;
    image.highlight = pixels.back();
    pixels.pop_back();
    image.outline = pixels;
    const SphereRay ray = sphere_ray(image, cam, sp.radius);
    EXPECT_LT(cv::norm(ray.centre - sp.centre), 1e-6);
    EXPECT_LT(cv::norm(ray.origin - h), 1e-6);
    EXPECT_NEAR(ray.direction.dot(cv::normalize(scene.light - h)), 1.0, 1e-12);
  }
}

TEST(CalibLights, RenderedSpheresWithinTolerance) {
  const test::SphereScene scene;
  const Intrinsics cam = test::camera(1600, 1280, 960, -0.05, 0.0);
  const cv::Mat image = render_spheres(cam, scene.spheres, scene.light, 2.0, 3);
  cv::Mat grey;
  image.convertTo(grey, CV_32F, 1.0 / 65535);
  const std::vector<SphereImage> found = detect_spheres(grey);
  ASSERT_EQ(found.size(), scene.spheres.size());
  std::vector<SphereRay> rays;
  // detect_spheres orders left to right: the scene's spheres are at x -110, -20, 110.
  const int order[] = {0, 2, 1};
  double worst_centre = 0;
  for (std::size_t i = 0; i < found.size(); ++i) {
    rays.push_back(sphere_ray(found[i], cam, 25));
    worst_centre = std::max(worst_centre, cv::norm(rays.back().centre - scene.spheres[std::size_t(order[i])].centre));
  }
  const LightFit fit = triangulate_light(rays);
  const double error = cv::norm(fit.position - scene.light);
  EXPECT_LT(worst_centre, 1.0);
  EXPECT_LE(error, 1.0);
  EXPECT_LT(fit.residual_rms_mm, 1.0);
  std::printf("lights: position error %.4f mm at %.0f mm, residual %.4f mm, worst sphere centre error %.4f mm\n", error,
              cv::norm(scene.light - scene.spheres[0].centre), fit.residual_rms_mm, worst_centre);
}

TEST(CalibLights, DarkImageHasNoSpheres) {
  EXPECT_TRUE(detect_spheres(cv::Mat(100, 100, CV_32F, cv::Scalar(0.02f))).empty());
}

}  // namespace
