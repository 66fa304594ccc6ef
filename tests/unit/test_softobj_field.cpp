// softobj: field identities and the shrink-wrap polygoniser against closed-form offset
// volumes (docs/softobj.md §6): every expected number comes from a formula.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "softobj/closest.hpp"
#include "softobj/field.hpp"
#include "softobj/mesh_measures.hpp"
#include "softobj/shrinkwrap.hpp"
#include "softobj/skeleton_json.hpp"
#include "softobj/tongue.hpp"

using namespace fest::softobj;
using Eigen::Vector3d;
using fest::TriMesh;

namespace {

Skeleton square(double side) {
  Skeleton s;
  s.vertices = {{0, 0, 0}, {side, 0, 0}, {side, side, 0}, {0, side, 0}};
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  return s;
}

struct Polygonized {
  TriMesh mesh;
  MeshMeasures m;
  double err;
};

Polygonized run(const Skeleton& s, double rho, double alpha = 15) {
  Field f(compile_terms(s));
  ShrinkwrapOptions o;
  o.iso = 1 / rho;
  o.alpha_deg = alpha;
  TriMesh mesh = shrinkwrap(f, o);
  Polygonized r{mesh, measure(mesh), max_iso_error(f, mesh, o.iso)};
  return r;
}

void expect_closed_on_surface(const Polygonized& p, double alpha, double lmax) {
  EXPECT_TRUE(p.m.closed);
  EXPECT_EQ(p.m.euler_characteristic, 2);
  EXPECT_LE(p.err, 1e-6);
  EXPECT_LE(p.m.max_edge, lmax * (1 + 1e-9));
  EXPECT_LE(p.m.max_normal_angle_deg, alpha + 1e-9);
  EXPECT_GT(p.m.volume, 0);
}

}  // namespace

TEST(SoftobjField, SquareIsDistanceToSquare) {
  // Inclusion-exclusion on two coplanar triangles: f = 1/dist(r, square) wherever the
  // closest point is inside or on the diagonal.
  Field f(compile_terms(square(20)));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.5, 19.5), h(-30, 30);
  for (int i = 0; i < 1000; ++i) {
    const Vector3d r(u(rng), u(rng), h(rng));
    if (std::abs(r.z()) < 1e-3) continue;
    const double expected = 1 / std::abs(r.z());
    EXPECT_NEAR(f.value(r), expected, 1e-12 * expected);
  }
}

TEST(SoftobjField, GradientMatchesDifferences) {
  Skeleton s = square(10);
  s.vertices.push_back({5, 5, 8});
  s.triangles.push_back({2, 3, 4});
  Field f(compile_terms(s));
  const Vector3d r(3, -4, 6);
  const auto e = f.eval(r);
  for (int k = 0; k < 3; ++k) {
    Vector3d d = Vector3d::Zero();
    d[k] = 1e-6;
    EXPECT_NEAR(e.grad[k], (f.value(r + d) - f.value(r - d)) / 2e-6, 1e-7);
  }
}

TEST(SoftobjField, ClosestPointRegions) {
  const Vector3d a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  EXPECT_TRUE(closest_on_triangle({-1, -1, 3}, a, b, c).isApprox(a));
  EXPECT_TRUE(closest_on_triangle({6, -1, 3}, a, b, c).isApprox(b));
  EXPECT_TRUE(closest_on_triangle({-1, 6, 3}, a, b, c).isApprox(c));
  EXPECT_TRUE(closest_on_triangle({2, -3, 1}, a, b, c).isApprox(Vector3d(2, 0, 0)));
  EXPECT_TRUE(closest_on_triangle({-3, 2, 1}, a, b, c).isApprox(Vector3d(0, 2, 0)));
  EXPECT_TRUE(closest_on_triangle({3, 3, 1}, a, b, c).isApprox(Vector3d(2, 2, 0)));
  EXPECT_TRUE(closest_on_triangle({1, 1, 5}, a, b, c).isApprox(Vector3d(1, 1, 0)));
}

TEST(SoftobjShrinkwrap, SphereVolume) {
  Skeleton s;
  s.vertices = {{1, 2, 3}};
  s.points = {0};
  const double v = 4.0 / 3 * M_PI * 1000;  // 4188.79
  // The mesh is inscribed: its volume lies below V, and above V (1 - 3 (1 - cos(alpha/sqrt 3)))
  // (a triangle whose vertex normals differ pairwise by <= alpha sinks at most
  // R (1 - cos(alpha/sqrt 3)) below the sphere; volume = area x depth / 3 per cone).
  const auto p10 = run(s, 10, 10);
  expect_closed_on_surface(p10, 10, 10);
  EXPECT_LT(p10.m.volume, v);
  EXPECT_GT(p10.m.volume, v * (1 - 3 * (1 - std::cos(10 * M_PI / 180 / std::sqrt(3.0)))));
  // The 0.5 % target is met from alpha = 7 degrees on.
  const auto p = run(s, 10, 7);
  expect_closed_on_surface(p, 7, 10);
  EXPECT_NEAR(p.m.volume, v, 0.005 * v);
  EXPECT_NEAR(p.m.area, 4 * M_PI * 100, 0.005 * 4 * M_PI * 100);
}

TEST(SoftobjShrinkwrap, CapsuleVolume) {
  Skeleton s;
  s.vertices = {{0, 0, 0}, {20, 0, 0}};
  s.segments = {{0, 1}};
  const auto p = run(s, 5, 10);
  expect_closed_on_surface(p, 10, 5);
  const double v = M_PI * 25 * 20 + 4.0 / 3 * M_PI * 125;  // 2094.40
  EXPECT_NEAR(p.m.volume, v, 0.005 * v);
}

TEST(SoftobjShrinkwrap, SquareSlabVolume) {
  const auto p = run(square(20), 5, 10);
  expect_closed_on_surface(p, 10, 5);
  const double A = 400, P = 80, r = 5;
  const double v = 2 * r * A + M_PI / 2 * r * r * P + 4.0 / 3 * M_PI * r * r * r;  // 7665.2
  EXPECT_NEAR(p.m.volume, v, 0.007 * v);
  EXPECT_NEAR(p.m.area, 2 * A + M_PI * r * P + 4 * M_PI * r * r, 0.007 * (2 * A + M_PI * r * P + 4 * M_PI * r * r));
}

TEST(SoftobjShrinkwrap, HexagonFanVolume) {
  Skeleton s;
  s.vertices.push_back({0, 0, 0});
  for (int i = 0; i < 6; ++i) s.vertices.push_back({10 * std::cos(i * M_PI / 3), 10 * std::sin(i * M_PI / 3), 0});
  for (int i = 0; i < 6; ++i) s.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  const auto p = run(s, 4, 10);
  expect_closed_on_surface(p, 10, 4);
  const double A = 6 * std::sqrt(3.0) / 4 * 100, P = 60, r = 4;
  const double v = 2 * r * A + M_PI / 2 * r * r * P + 4.0 / 3 * M_PI * r * r * r;  // 3854.6
  EXPECT_NEAR(p.m.volume, v, 0.01 * v);
}

TEST(SoftobjShrinkwrap, TongueIsClosedAndOnSurface) {
  const Skeleton s = tongue_skeleton(neutral_tongue(), TongueLayout::default10, 6);
  const CompiledSkeleton c = compile_terms(s);
  EXPECT_EQ(c.euler_characteristic, 1);
  EXPECT_EQ(c.shared_edges, 11);
  EXPECT_NEAR(c.total_charge, 1, 1e-12);
  const auto p = run(s, 6, 15);
  expect_closed_on_surface(p, 15, 6);
}

TEST(SoftobjTongue, PointsFromFormulas) {
  const auto vl = tongue_points(neutral_tongue());
  const double d = M_PI / 180;
  const Vector3d v1(15 * std::sin(15 * d), -15 * std::cos(15 * d), 0);
  EXPECT_TRUE((vl[1] - v1).norm() < 1e-12);
  const Vector3d v2 = v1 + 18 * Vector3d(-std::sin(186 * d), std::cos(186 * d), 0);
  EXPECT_TRUE((vl[2] - v2).norm() < 1e-12);
  EXPECT_TRUE((vl[5] - (v1 + 14 * Vector3d(std::sin(10 * d), 0, std::cos(10 * d)))).norm() < 1e-12);
}

TEST(SoftobjJson, RoundTripAndBadInput) {
  const Skeleton s = tongue_skeleton(neutral_tongue(), TongueLayout::paper9, 6);
  const Skeleton t = decode_skeleton(encode_skeleton(s));
  EXPECT_EQ(t.triangles, s.triangles);
  for (std::size_t i = 0; i < s.vertices.size(); ++i) EXPECT_EQ(t.vertices[i], s.vertices[i]);
  EXPECT_THROW(decode_skeleton("{\"vertices\": [[0,0,0]], \"triangles\": [[0,1,2]]}"), fest::Error);
  EXPECT_THROW(decode_skeleton("{\"vertices\": [[0,0]]}"), fest::Error);
  EXPECT_THROW(decode_skeleton("{"), fest::Error);
  EXPECT_THROW(decode_skeleton("{\"vertices\": [], \"triangles\": []}"), fest::Error);
}

TEST(SoftobjShrinkwrap, FlatFacesGetLargerTrianglesThanTheRim) {
  // Square slab 20 x 20, rho = 5, alpha = 15, L_max = 3 rho: triangles whose centroid
  // lies over the square's interior (the flat faces, 2 < x, y < 18) against the rounded
  // rim (outside the square).
  Field f(compile_terms(square(20)));
  ShrinkwrapOptions o;
  o.iso = 0.2;
  o.lmax = 15;
  const TriMesh m = shrinkwrap(f, o);
  double flat = 0, rim = 0;
  int nf = 0, nr = 0;
  for (auto fh : m.faces()) {
    std::array<Vector3d, 3> q;
    int k = 0;
    for (auto v : m.fv_range(fh)) q[k++] = Vector3d(m.point(v)[0], m.point(v)[1], m.point(v)[2]);
    const Vector3d c = (q[0] + q[1] + q[2]) / 3;
    const double area = 0.5 * (q[1] - q[0]).cross(q[2] - q[0]).norm();
    if (c.x() > 2 && c.x() < 18 && c.y() > 2 && c.y() < 18) flat += area, ++nf;
    else if (c.x() < 0 || c.x() > 20 || c.y() < 0 || c.y() > 20) rim += area, ++nr;
  }
  ASSERT_GT(nf, 0);
  ASSERT_GT(nr, 0);
  EXPECT_GE((flat / nf) / (rim / nr), 4.0) << "flat " << flat / nf << " rim " << rim / nr;
}
