// Screen-mask polygons (lib/raycast/screen_polygon.hpp, docs/volrender.md "--screen-mask"):
// pixel-centre inclusion counted from geometry, polygons that tile the screen claim every
// pixel exactly once even when centres lie on their shared edges, bad polygons refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "raycast/screen_polygon.hpp"

using fest::raycast::ScreenPoint;
using fest::raycast::polygon_pixel_mask;

namespace {
std::size_t count(const std::vector<std::uint8_t>& m) {
  std::size_t n = 0;
  for (auto v : m) n += v;
  return n;
}
}  // namespace

TEST(RaycastScreenPolygon, RectangleOnPixelCornersHoldsItsPixels) {
  // [2,7] x [3,5]: centres i + 1/2 in (2,7) for i = 2..6, j + 1/2 in (3,5) for j = 3, 4
  const auto m = polygon_pixel_mask({{2, 3}, {7, 3}, {7, 5}, {2, 5}}, 10, 8);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 10; ++i) EXPECT_EQ(m[static_cast<std::size_t>(j) * 10 + i], i >= 2 && i <= 6 && j >= 3 && j <= 4) << i << "," << j;
}

TEST(RaycastScreenPolygon, RightTriangleHypotenuseCentresGoToPlusX) {
  // x, y >= 0, x + y <= 20: centres with i + j + 1 < 20 inside, the 20 with i + j = 19 on
  // the hypotenuse, outside by the tie rule -> 19 * 20 / 2
  EXPECT_EQ(count(polygon_pixel_mask({{0, 0}, {20, 0}, {0, 20}}, 40, 30)), 190u);
  EXPECT_EQ(count(polygon_pixel_mask({{0, 20}, {20, 0}, {0, 0}}, 40, 30)), 190u);
  // the mirrored triangle x + y >= 20 in [0,20]^2 takes the hypotenuse: 400 - 190
  EXPECT_EQ(count(polygon_pixel_mask({{20, 0}, {20, 20}, {0, 20}}, 40, 30)), 210u);
}

TEST(RaycastScreenPolygon, DiagonalTrianglesTileTheScreenOnce) {
  // a square screen: every diagonal centre lies on two triangles' shared edge
  for (const int n : {40, 41, 64}) {
    const double c = n / 2.0;
    const std::vector<std::vector<ScreenPoint>> parts = {{{0, 0}, {double(n), 0}, {c, c}},
                                                         {{double(n), 0}, {double(n), double(n)}, {c, c}},
                                                         {{0, double(n)}, {double(n), double(n)}, {c, c}},
                                                         {{0, 0}, {0, double(n)}, {c, c}}};
    std::vector<int> owners(static_cast<std::size_t>(n) * n, 0);
    for (const auto& p : parts) {
      const auto m = polygon_pixel_mask(p, n, n);
      for (std::size_t k = 0; k < m.size(); ++k) owners[k] += m[k];
    }
    for (std::size_t k = 0; k < owners.size(); ++k) ASSERT_EQ(owners[k], 1) << "n " << n << " pixel " << k;
  }
}

TEST(RaycastScreenPolygon, FanAroundAnOffGridPointTilesItsHull) {
  // a convex octagon cut into a fan around an interior point at irrational-looking
  // coordinates: each centre inside the octagon belongs to exactly one fan triangle
  std::vector<ScreenPoint> hull;
  for (int k = 0; k < 8; ++k) hull.push_back({32 + 25 * std::cos(0.785398 * k + 0.3), 24 + 20 * std::sin(0.785398 * k + 0.3)});
  const ScreenPoint centre{30.123456789, 25.987654321};
  const auto whole = polygon_pixel_mask(hull, 64, 48);
  std::vector<int> owners(whole.size(), 0);
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const auto m = polygon_pixel_mask({centre, hull[k], hull[(k + 1) % hull.size()]}, 64, 48);
    for (std::size_t q = 0; q < m.size(); ++q) owners[q] += m[q];
  }
  for (std::size_t q = 0; q < whole.size(); ++q) ASSERT_EQ(owners[q], whole[q]) << q;
}

TEST(RaycastScreenPolygon, NonConvexL) {
  EXPECT_EQ(count(polygon_pixel_mask({{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}, 40, 30)), 75u);
}

TEST(RaycastScreenPolygon, BadPolygonsRefused) {
  EXPECT_THROW(polygon_pixel_mask({{0, 0}, {1, 1}}, 4, 4), std::invalid_argument);
  EXPECT_THROW(polygon_pixel_mask({{0, 0}, {1, NAN}, {0, 2}}, 4, 4), std::invalid_argument);
  EXPECT_THROW(polygon_pixel_mask({{0, 0}, {1, 1}, {2, 2}}, 4, 4), std::invalid_argument);
}
