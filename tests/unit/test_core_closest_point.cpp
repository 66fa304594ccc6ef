// lib/core/closest_point.hpp: every Voronoi region of a right triangle, answers worked
// out by hand, with a minimal vector type (the header needs dot, +, -, scalar *).
#include <gtest/gtest.h>

#include "core/closest_point.hpp"

namespace {

struct V {
  double x, y, z;
  double dot(const V& o) const { return x * o.x + y * o.y + z * o.z; }
};
V operator+(const V& a, const V& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator-(const V& a, const V& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(double s, const V& a) { return {s * a.x, s * a.y, s * a.z}; }
V operator*(const V& a, double s) { return s * a; }

void expect_near(const V& got, const V& want) {
  EXPECT_NEAR(got.x, want.x, 1e-12);
  EXPECT_NEAR(got.y, want.y, 1e-12);
  EXPECT_NEAR(got.z, want.z, 1e-12);
}

}  // namespace

TEST(CoreClosestPoint, EveryRegionOfARightTriangle) {
  const V a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
  auto closest = [&](V p) { return fest::closest_point_on_triangle(p, a, b, c); };
  expect_near(closest({-1, -1, 3}), a);             // vertex regions
  expect_near(closest({3, -1, 0}), b);
  expect_near(closest({-1, 3, 0}), c);
  expect_near(closest({1, -2, 1}), {1, 0, 0});     // edge ab
  expect_near(closest({-2, 1, 0}), {0, 1, 0});     // edge ac
  expect_near(closest({2, 2, 0}), {1, 1, 0});      // edge bc: the foot of the perpendicular
  expect_near(closest({0.5, 0.5, 4}), {0.5, 0.5, 0});  // face: straight down
}

TEST(CoreClosestPoint, TheFaceRegionIsTheCallers) {
  const V a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
  double weights[3] = {0, 0, 0};
  const V marker{9, 9, 9};
  const V got = fest::closest_point_on_triangle(V{0.5, 0.5, 1}, a, b, c, [&](double va, double vb, double vc) {
    weights[0] = va, weights[1] = vb, weights[2] = vc;
    return marker;
  });
  expect_near(got, marker);
  // Barycentric weights of (0.5, 0.5) in a (0,0), b (2,0), c (0,2): v = x/2, w = y/2,
  // u = 1 - v - w, so 0.5, 0.25, 0.25 of the unnormalised weights' sum.
  const double sum = weights[0] + weights[1] + weights[2];
  EXPECT_NEAR(weights[0] / sum, 0.5, 1e-12);
  EXPECT_NEAR(weights[1] / sum, 0.25, 1e-12);
  EXPECT_NEAR(weights[2] / sum, 0.25, 1e-12);
}
