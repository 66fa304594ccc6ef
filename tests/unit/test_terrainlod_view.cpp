// extract's view helpers against geometry worked out by hand: clip_to_dem (the part of a
// triangle inside the DEM rectangle, on the triangle's plane, with cut points shared by
// the two triangles of an edge) and frame_box (every corner of the box projects inside
// the image, and one touches the margin: the nearest such camera).

#include <array>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "terrainlod/auto_camera.hpp"
#include "terrainlod/dem_clip.hpp"

namespace {

using namespace fest::terrainlod;
using V = TileTriangulation::Vertex;

double area(const std::vector<std::array<GridPoint, 3>>& tris) {
  double a = 0;
  for (const auto& t : tris) a += twice_area(t[0], t[1], t[2]) / 2;
  return a;
}

TEST(TerrainlodClip, InsideKeptOutsideDropped) {
  EXPECT_EQ(clip_to_dem({V{0, 0, 1}, V{2, 0, 1}, V{0, 2, 1}}, 2, 2).size(), 1u);
  EXPECT_TRUE(clip_to_dem({V{3, 0, 1}, V{5, 0, 1}, V{3, 2, 1}}, 2, 2).empty());
  // Touching the edge with one side only: nothing of positive area inside.
  EXPECT_TRUE(clip_to_dem({V{2, 0, 1}, V{5, 0, 1}, V{2, 2, 1}}, 2, 9).empty());
}

TEST(TerrainlodClip, AreaAndPlane) {
  // Triangle x, y >= 0, x + y <= 4 (area 8) on the plane z = x + 2y, cut at x = 2 and
  // y = 3: minus the corner x > 2 (area 2) and the corner y > 3 (area 1/2) = 5.5.
  const auto pieces = clip_to_dem({V{0, 0, 0}, V{4, 0, 4}, V{0, 4, 8}}, 2, 3);
  EXPECT_NEAR(area(pieces), 5.5, 1e-12);
  for (const auto& t : pieces)
    for (const auto& p : t) {
      EXPECT_LE(p.x, 2.0);
      EXPECT_LE(p.y, 3.0);
      EXPECT_NEAR(p.z, p.x + 2 * p.y, 1e-12);
      EXPECT_GT(twice_area(t[0], t[1], t[2]), 0);  // counter-clockwise kept
    }
}

TEST(TerrainlodClip, SharedEdgeSameCutPoint) {
  // Edge (1, 1, 0.3) - (7, 3, 9.1) shared by two triangles walking it in opposite
  // directions; cut at x = 4: both get the same point, bit for bit.
  const V a{1, 1, 0.3}, b{7, 3, 9.1};
  const auto left = clip_to_dem({a, b, V{1, 3, 2}}, 4, 100);
  const auto right = clip_to_dem({b, a, V{6, 0, 5}}, 4, 100);
  auto on_cut = [](const std::vector<std::array<GridPoint, 3>>& tris, double y_min, double y_max) {
    std::vector<GridPoint> pts;
    for (const auto& t : tris)
      for (const auto& p : t)
        if (p.x == 4 && p.y > y_min && p.y < y_max) pts.push_back(p);
    return pts;
  };
  // The edge crosses x = 4 at y = 2.
  const auto l = on_cut(left, 1.9, 2.1), r = on_cut(right, 1.9, 2.1);
  ASSERT_FALSE(l.empty());
  ASSERT_FALSE(r.empty());
  EXPECT_EQ(l[0].y, r[0].y);
  EXPECT_EQ(l[0].z, r[0].z);
  EXPECT_NEAR(l[0].z, 0.3 + 0.5 * (9.1 - 0.3), 1e-12);
}

TEST(TerrainlodAutoCamera, EveryCornerInsideOneOnTheMargin) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const double x0 = 1000 * u(rng), y0 = 1000 * u(rng), z0 = 100 * u(rng);
    const WorldBox box{x0, y0, z0, x0 + 10 + 5000 * u(rng), y0 + 10 + 5000 * u(rng), z0 + 1000 * u(rng)};
    const auto& names = camera_preset_names();
    const ViewDirection dir = camera_preset(names[static_cast<std::size_t>(trial) % names.size()]);
    const int W = 1280, H = 800;
    const double margin = 0.04;
    const Camera c = frame_box(box, dir, W, H, 45, margin);
    EXPECT_NO_THROW(check_camera(c));
    using Vec = std::array<double, 3>;
    auto sub = [](const Vec& a, const Vec& b) { return Vec{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    auto dot = [](const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    auto unit = [&](const Vec& a) { const double n = std::sqrt(dot(a, a)); return Vec{a[0] / n, a[1] / n, a[2] / n}; };
    const Vec f = unit(sub(c.target, c.eye));
    const Vec r = unit({f[1] * c.up[2] - f[2] * c.up[1], f[2] * c.up[0] - f[0] * c.up[2], f[0] * c.up[1] - f[1] * c.up[0]});
    const Vec up{r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
    const double fpx = (H / 2.0) / std::tan(45 * M_PI / 360);
    double worst = 0;  // largest |offset| / half-size over the corners
    for (int k = 0; k < 8; ++k) {
      const Vec p{k & 1 ? box.x1 : box.x0, k & 2 ? box.y1 : box.y0, k & 4 ? box.z1 : box.z0};
      const Vec d = sub(p, c.eye);
      const double z = dot(d, f);
      ASSERT_GT(z, c.near);
      ASSERT_LT(z, c.far);
      const double sx = fpx * dot(d, r) / z, sy = fpx * dot(d, up) / z;
      EXPECT_LE(std::abs(sx), W / 2.0 * (1 - margin) + 1e-6);
      EXPECT_LE(std::abs(sy), H / 2.0 * (1 - margin) + 1e-6);
      worst = std::max({worst, std::abs(sx) / (W / 2.0 * (1 - margin)), std::abs(sy) / (H / 2.0 * (1 - margin))});
    }
    EXPECT_NEAR(worst, 1.0, 1e-6) << "the nearest camera: some corner on the margin";
  }
}

TEST(TerrainlodAutoCamera, UnknownPresetNamesTheChoices) {
  try {
    camera_preset("sideways");
    FAIL();
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("overview"), std::string::npos);
  }
}

}  // namespace
