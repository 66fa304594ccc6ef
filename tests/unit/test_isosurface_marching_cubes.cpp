// Exact extraction on analytic fields (docs/isosurf.md "Tests").
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "isosurface/marching_cubes.hpp"
#include "isosurface/mesh_stats.hpp"

using namespace fest::isosurface;
using fest::volume_pyramid::MinMaxPyramid;
using fest::volume_pyramid::ScalarGrid;

namespace {

ScalarGrid field(std::size_t n, const std::function<double(double, double, double)>& f, double h = 1.0) {
  ScalarGrid g;
  g.dims = {n, n, n};
  g.axes = {h, 0, 0, 0, h, 0, 0, 0, h};
  g.values.resize(g.size());
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) g.values[g.index(i, j, k)] = static_cast<float>(f(i * h, j * h, k * h));
  return g;
}

// f = R - |x - c|: inside (f >= 0) is the ball, values high inside.
ScalarGrid sphere(std::size_t n, double R) {
  const double c = (n - 1) / 2.0;
  return field(n, [=](double x, double y, double z) { return R - std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c)); });
}

Surface extract(const ScalarGrid& g, float iso, ExtractOptions o = {}) {
  const MinMaxPyramid p(g, 1);
  return extract_isosurface(g, iso, o, &p);
}

}  // namespace

TEST(MarchingCubes, SphereClosedGenusZeroOutward) {
  const auto s = extract(sphere(40, 15.3), 0.0f);
  const auto m = mesh_stats(s);
  EXPECT_TRUE(m.closed);
  EXPECT_EQ(m.nonmanifold_vertices, 0u);
  EXPECT_EQ(m.components, 1u);
  EXPECT_EQ(m.euler, 2);
  EXPECT_EQ(m.genus, 0);
  EXPECT_EQ(m.triangles, 2 * (m.vertices - 2));
  EXPECT_GT(m.volume, 0);  // oriented outwards
  EXPECT_NEAR(m.volume, 4.0 / 3.0 * M_PI * std::pow(15.3, 3), 0.01 * m.volume);
}

// Second order: relative area and volume errors shrink >= 3.5x when R/h doubles.
TEST(MarchingCubes, SphereConvergesAtSecondOrder) {
  double prev_a = 0, prev_v = 0;
  for (double R : {12.5, 25.0, 50.0}) {
    const std::size_t n = static_cast<std::size_t>(2 * R + 6);
    const auto m = mesh_stats(extract(sphere(n, R), 0.0f));
    ASSERT_TRUE(m.closed);
    const double ea = std::abs(m.area / (4 * M_PI * R * R) - 1), ev = std::abs(m.volume / (4.0 / 3.0 * M_PI * R * R * R) - 1);
    if (prev_a > 0) {
      EXPECT_GT(prev_a / ea, 3.5) << "R " << R;
      EXPECT_GT(prev_v / ev, 3.5) << "R " << R;
    }
    prev_a = ea, prev_v = ev;
  }
}

TEST(MarchingCubes, TorusHasGenusOne) {
  const double R = 12, r = 5, c = 19.5;
  const auto g = field(40, [=](double x, double y, double z) {
    const double q = std::sqrt((x - c) * (x - c) + (y - c) * (y - c)) - R;
    return r - std::sqrt(q * q + (z - c) * (z - c));
  });
  const auto m = mesh_stats(extract(g, 0.0f));
  EXPECT_TRUE(m.closed);
  EXPECT_EQ(m.euler, 0);
  EXPECT_EQ(m.genus, 1);
  EXPECT_NEAR(m.volume, 2 * M_PI * M_PI * R * r * r, 0.02 * m.volume);
}

TEST(MarchingCubes, TwoSpheresTwoComponents) {
  const auto g = field(40, [](double x, double y, double z) {
    const double a = 8 - std::sqrt((x - 10) * (x - 10) + (y - 20) * (y - 20) + (z - 20) * (z - 20));
    const double b = 8 - std::sqrt((x - 29) * (x - 29) + (y - 20) * (y - 20) + (z - 20) * (z - 20));
    return std::max(a, b);
  });
  const auto m = mesh_stats(extract(g, 0.0f));
  EXPECT_TRUE(m.closed);
  EXPECT_EQ(m.components, 2u);
  EXPECT_EQ(m.euler, 4);
}

// An axis-aligned plane: every vertex exactly on it; area = the cross-section.
TEST(MarchingCubes, PlaneIsExact) {
  const auto g = field(17, [](double x, double, double) { return 10.25 - x; });
  const auto s = extract(g, 0.0f);
  for (std::size_t v = 0; v < s.vertices(); ++v) EXPECT_EQ(s.xyz[3 * v], 10.25f);
  EXPECT_NEAR(mesh_stats(s).area, 16.0 * 16.0, 1e-9);
}

// Random fields, including every ambiguous configuration that noise produces: the pyramid
// path equals the brute-force scan, two threads equal one, and the surface of a capped
// (outside-bordered) field is closed under both face rules.
TEST(MarchingCubes, NoiseIsClosedAndDeterministic) {
  std::uint32_t state = 12345;
  auto rnd = [&] { return (state = state * 1664525u + 1013904223u) / 4294967296.0; };
  for (FaceRule rule : {FaceRule::decider, FaceRule::separate}) {
    ScalarGrid g;
    g.dims = {23, 19, 21};
    g.values.resize(g.size());
    for (std::size_t k = 0; k < g.dims[2]; ++k)
      for (std::size_t j = 0; j < g.dims[1]; ++j)
        for (std::size_t i = 0; i < g.dims[0]; ++i) {
          const bool border = i == 0 || j == 0 || k == 0 || i + 1 == g.dims[0] || j + 1 == g.dims[1] || k + 1 == g.dims[2];
          g.values[g.index(i, j, k)] = border ? -1.0f : static_cast<float>(rnd() - 0.5);
        }
    ExtractOptions o;
    o.face_rule = rule;
    const MinMaxPyramid p(g, 1);
    const auto a = extract_isosurface(g, 0.0f, o, &p);
    const auto b = extract_isosurface(g, 0.0f, o, nullptr);
    o.threads = 2;
    const auto c = extract_isosurface(g, 0.0f, o, &p);
    EXPECT_EQ(a.xyz, b.xyz);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.xyz, c.xyz);
    EXPECT_EQ(a.triangles, c.triangles);
    const auto m = mesh_stats(a);
    EXPECT_TRUE(m.closed) << m.boundary_edges << " " << m.nonmanifold_edges << " " << m.orientation_conflicts;
    EXPECT_EQ(m.triangles, 2 * (m.vertices - m.euler)) << m.boundary_edges << " " << m.nonmanifold_edges << " " << m.orientation_conflicts << " deg " << m.degenerate_triangles;
  }
}

// Mirroring the index->world map (negative determinant) keeps normals outward.
TEST(MarchingCubes, MirroredAxesKeepOrientation) {
  auto g = sphere(24, 8.2);
  g.axes = {-1, 0, 0, 0, 1, 0, 0, 0, 1};
  EXPECT_GT(mesh_stats(extract(g, 0.0f)).volume, 0);
}
