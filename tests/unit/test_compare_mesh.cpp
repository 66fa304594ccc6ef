// Expected values here are geometry worked out by hand, noted next to each case.
#include <gtest/gtest.h>

#include <cmath>

#include "compare/mesh_compare.hpp"
#include "compare/triangle_tree.hpp"

using fest::Mesh;
using fest::compare::Vec3;

namespace {

// Axis-aligned cube [lo, hi]^3 as 6 quads, outward orientation.
Mesh cube(double lo, double hi) {
  Mesh m;
  Mesh::VertexHandle v[8];
  for (int i = 0; i < 8; ++i)
    v[i] = m.add_vertex(Mesh::Point(i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo));
  m.add_face(v[0], v[2], v[3], v[1]);  // z = lo
  m.add_face(v[4], v[5], v[7], v[6]);  // z = hi
  m.add_face(v[0], v[1], v[5], v[4]);  // y = lo
  m.add_face(v[2], v[6], v[7], v[3]);  // y = hi
  m.add_face(v[0], v[4], v[6], v[2]);  // x = lo
  m.add_face(v[1], v[3], v[7], v[5]);  // x = hi
  return m;
}

// Unit square in the plane z = h, split into two triangles.
Mesh square(double h) {
  Mesh m;
  auto a = m.add_vertex({0, 0, h}), b = m.add_vertex({1, 0, h}), c = m.add_vertex({1, 1, h}), d = m.add_vertex({0, 1, h});
  m.add_face(a, b, c);
  m.add_face(a, c, d);
  return m;
}

// n x m grid glued into a torus (every vertex has valence 6 after triangulation).
Mesh torus(int n, int k) {
  Mesh m;
  std::vector<Mesh::VertexHandle> v;
  const double R = 2, r = 0.5;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) {
      const double u = 2 * M_PI * i / n, w = 2 * M_PI * j / k;
      v.push_back(m.add_vertex({(R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w)}));
    }
  auto at = [&](int i, int j) { return v[static_cast<std::size_t>(((i + n) % n) * k + (j + k) % k)]; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

}  // namespace

TEST(ClosestPoint, RegionsOfATriangle) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  using fest::compare::closest_point_on_triangle;
  EXPECT_TRUE(closest_point_on_triangle({0.25, 0.25, 3}, a, b, c).isApprox(Vec3(0.25, 0.25, 0)));  // face
  EXPECT_TRUE(closest_point_on_triangle({-1, -1, 0}, a, b, c).isApprox(a));                         // vertex
  EXPECT_TRUE(closest_point_on_triangle({0.5, -2, 0}, a, b, c).isApprox(Vec3(0.5, 0, 0)));          // edge ab
  EXPECT_TRUE(closest_point_on_triangle({1, 1, 0}, a, b, c).isApprox(Vec3(0.5, 0.5, 0)));           // edge bc
}

TEST(SurfaceDistance, IdenticalMeshesAreAtZero) {
  const Mesh t = torus(24, 12);
  const auto d = fest::compare::surface_distance(t, t, 20000);
  EXPECT_EQ(d.hausdorff, 0.0);
  EXPECT_EQ(d.rms, 0.0);
  EXPECT_EQ(d.samples_a, 24u * 12u + 20000u);
}

TEST(SurfaceDistance, ParallelSquaresAreTheirGapApart) {
  // Every point of one square is exactly h above the other: Hausdorff = RMS = mean = h.
  const auto d = fest::compare::surface_distance(square(0), square(0.25), 5000);
  EXPECT_NEAR(d.hausdorff, 0.25, 1e-12);
  EXPECT_NEAR(d.rms, 0.25, 1e-12);
  EXPECT_NEAR(d.mean, 0.25, 1e-12);
}

TEST(SurfaceDistance, NestedCubes) {
  // Outer cube [-0.5,1.5]^3 around inner [0,1]^3: an outer corner is sqrt(3)/2 from the
  // inner cube (its nearest inner corner); every inner point is 0.5 from the outer face
  // it faces. Hence max_b_to_a = sqrt(0.75) and max_a_to_b = 0.5 (outer faces are
  // exactly 0.5 away all over the inner surface).
  const auto d = fest::compare::surface_distance(cube(0, 1), cube(-0.5, 1.5), 20000);
  EXPECT_NEAR(d.max_a_to_b, 0.5, 1e-12);
  EXPECT_NEAR(d.max_b_to_a, std::sqrt(0.75), 1e-12);
  EXPECT_NEAR(d.hausdorff, std::sqrt(0.75), 1e-12);
}

TEST(Topology, ClosedCubeIsGenusZero) {
  const auto t = fest::compare::mesh_topology(cube(0, 1));
  EXPECT_EQ(t.vertices, 8u);
  EXPECT_EQ(t.faces, 6u);
  EXPECT_EQ(t.edges, 12u);
  EXPECT_EQ(t.euler, 2);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.boundary_loops, 0u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.closed());
}

TEST(Topology, TorusIsGenusOne) {
  const auto t = fest::compare::mesh_topology(torus(16, 8));
  EXPECT_EQ(t.euler, 0);
  EXPECT_EQ(t.genus, 1);
  EXPECT_EQ(t.boundary_loops, 0u);
}

TEST(Topology, SquareHasOneBoundaryLoop) {
  const auto t = fest::compare::mesh_topology(square(0));
  EXPECT_EQ(t.boundary_edges, 4u);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.genus, 0);  // a disc: chi = 1 = 2 - 0 - 1
}

TEST(Topology, TwoComponentsAndAnIsolatedVertex) {
  Mesh m = cube(0, 1);
  const Mesh other = square(5);
  std::vector<Mesh::VertexHandle> v;
  for (auto h : other.vertices()) v.push_back(m.add_vertex(other.point(h)));
  m.add_face(v[0], v[1], v[2]);
  m.add_face(v[0], v[2], v[3]);
  m.add_vertex({9, 9, 9});
  const auto t = fest::compare::mesh_topology(m);
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.isolated_vertices, 1u);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.euler, 3);  // sphere 2 + disc 1
}

TEST(SurfaceDistance, SameFiguresForEveryThreadCount) {
  const Mesh a = torus(24, 12), b = cube(-1, 1);
  const auto one = fest::compare::surface_distance(a, b, 5000, 7, 1);
  const auto four = fest::compare::surface_distance(a, b, 5000, 7, 4);
  EXPECT_EQ(one.hausdorff, four.hausdorff);
  EXPECT_EQ(one.rms, four.rms);  // bit-identical: fixed chunks, ordered sums
  EXPECT_EQ(one.mean, four.mean);
}
