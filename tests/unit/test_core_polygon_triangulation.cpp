// core/polygon_triangulation: convex polygons give the fan (what fest always wrote),
// concave ones ears whose areas add up to the polygon's own (shoelace formula).
#include <gtest/gtest.h>

#include <cmath>

#include "core/polygon_triangulation.hpp"

namespace {

using Corners = std::vector<std::array<double, 3>>;

double triangle_area(const Corners& c, const std::array<std::size_t, 3>& t) {
  const auto &a = c[t[0]], &b = c[t[1]], &d = c[t[2]];
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = d[0] - a[0], vy = d[1] - a[1];
  return 0.5 * std::fabs(ux * vy - uy * vx);
}

double shoelace(const Corners& c) {  // in the z = 0 plane
  double twice = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto& p = c[i];
    const auto& q = c[(i + 1) % c.size()];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * std::fabs(twice);
}

double sum_area(const Corners& c) {
  double s = 0;
  for (const auto& t : fest::triangulate_polygon(c)) s += triangle_area(c, t);
  return s;
}

TEST(PolygonTriangulation, ConvexIsTheFan) {
  const Corners hexagon = {{2, 0, 0}, {1, 1.7, 0}, {-1, 1.7, 0}, {-2, 0, 0}, {-1, -1.7, 0}, {1, -1.7, 0}};
  const auto t = fest::triangulate_polygon(hexagon);
  ASSERT_EQ(t.size(), 4u);
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_EQ(t[k], (std::array<std::size_t, 3>{0, k + 1, k + 2}));
  // Clockwise and tilted out of every coordinate plane: still the fan.
  const Corners tilted = {{0, 0, 0}, {0, 1, 1}, {1, 1, 2}, {1, 0, 1}};
  EXPECT_EQ(fest::triangulate_polygon(tilted),
            (std::vector<std::array<std::size_t, 3>>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_TRUE(fest::triangulate_polygon({{0, 0, 0}, {1, 0, 0}}).empty());
}

TEST(PolygonTriangulation, ConcaveEarsCoverThePolygonOnly) {
  // An L (area 3) whose first corner is the reflex one: its fan leaves the polygon.
  const Corners l_shape = {{1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 2, 0}};
  EXPECT_EQ(fest::triangulate_polygon(l_shape).size(), 4u);
  EXPECT_DOUBLE_EQ(sum_area(l_shape), 3.0);
  EXPECT_DOUBLE_EQ(shoelace(l_shape), 3.0);
  // A square with a slit to its centre, visiting the slit's corners twice (assimp's
  // concave_polygon.obj is such a polygon).
  const Corners slit = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  EXPECT_EQ(fest::triangulate_polygon(slit).size(), 5u);
  EXPECT_NEAR(sum_area(slit), 4.0, 1e-12);
}

TEST(PolygonTriangulation, StarWithManyReflexCorners) {
  Corners star;
  const double pi = std::acos(-1.0);
  for (int k = 0; k < 20; ++k) {
    const double r = k % 2 ? 0.4 : 1.0, angle = 2 * pi * k / 20;
    star.push_back({r * std::cos(angle), r * std::sin(angle), 0});
  }
  EXPECT_EQ(fest::triangulate_polygon(star).size(), 18u);
  EXPECT_NEAR(sum_area(star), shoelace(star), 1e-12);
}

}  // namespace
