// lib/decimate: quadrics against plain geometry, and the collapse engine on meshes whose
// simplest exact form is known (a subdivided cube is a cube, a subdivided square a square).

#include <cmath>
#include <array>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "compare/mesh_compare.hpp"
#include "core/error.hpp"
#include "decimate/quadric.hpp"
#include "decimate/simplify.hpp"

namespace {

using fest::Mesh;
using fest::decimate::Quadric;

TEST(DecimateQuadric, PlaneQuadricIsAreaTimesSquaredDistance) {
  const double p[3] = {0, 0, 1}, q[3] = {2, 0, 1}, r[3] = {0, 3, 1};
  const Quadric Q = Quadric::triangle(p, q, r, 3, 3.0);  // weight = area 3
  const double v[3] = {5, -7, 4};
  EXPECT_NEAR(Q.evaluate(v), 3.0 * 9.0, 1e-12);  // distance to z = 1 is 3
  EXPECT_NEAR(Q.evaluate(p), 0.0, 1e-12);
}

TEST(DecimateQuadric, ThreePlanesMeetAtTheirCorner) {
  // Planes x = 1, y = 2, z = 3 through triangles; the minimiser is (1, 2, 3), cost 0.
  Quadric sum(3);
  const double a[3][3][3] = {{{1, 0, 0}, {1, 1, 0}, {1, 0, 1}}, {{0, 2, 0}, {0, 2, 1}, {1, 2, 0}}, {{0, 0, 3}, {1, 0, 3}, {0, 1, 3}}};
  for (const auto& t : a) sum += Quadric::triangle(t[0], t[1], t[2], 3, 1.0);
  double v[3];
  ASSERT_TRUE(sum.minimise(v));
  EXPECT_NEAR(v[0], 1, 1e-12);
  EXPECT_NEAR(v[1], 2, 1e-12);
  EXPECT_NEAR(v[2], 3, 1e-12);
  double packed[Quadric::packed_size(3)] = {};
  sum.add_to_packed(packed);
  double w[3];
  ASSERT_TRUE(Quadric::minimise_packed(packed, 3, w));
  EXPECT_NEAR(w[0], 1, 1e-12);
  EXPECT_NEAR(Quadric::evaluate_packed(packed, 3, w), 0.0, 1e-20);
}

TEST(DecimateQuadric, GeneralisedQuadricVanishesOnTheTriangle) {
  // GH98: a point of the triangle in R^5 (position + 2 attributes) costs nothing.
  const double p[5] = {0, 0, 0, 0.1, 0.2}, q[5] = {1, 0, 0, 0.5, 0.2}, r[5] = {0, 1, 0, 0.1, 0.9};
  const Quadric Q = Quadric::triangle(p, q, r, 5, 1.0);
  double m[5];
  for (int i = 0; i < 5; ++i) m[i] = 0.2 * p[i] + 0.3 * q[i] + 0.5 * r[i];
  EXPECT_NEAR(Q.evaluate(m), 0.0, 1e-14);
  m[4] += 0.5;  // off the triangle's plane in R^5 by an attribute change only
  EXPECT_GT(Q.evaluate(m), 1e-3);
}

// A cube [0,1]^3 with each face split into n x n squares, two triangles each.
Mesh subdivided_cube(int n) {
  Mesh m;
  std::map<std::array<long, 3>, Mesh::VertexHandle> index;
  auto vertex = [&](double x, double y, double z) {
    const std::array<long, 3> key{std::lround(x * n), std::lround(y * n), std::lround(z * n)};
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    return index[key] = m.add_vertex(OpenMesh::Vec3d(x, y, z));
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto pt = [&](int a, int b) {
            double c[3];
            c[axis] = side;
            c[(axis + 1) % 3] = static_cast<double>(a) / n;
            c[(axis + 2) % 3] = static_cast<double>(b) / n;
            return vertex(c[0], c[1], c[2]);
          };
          auto v00 = pt(i, j), v10 = pt(i + 1, j), v11 = pt(i + 1, j + 1), v01 = pt(i, j + 1);
          if (side == 1) {
            m.add_face(v00, v10, v11);
            m.add_face(v00, v11, v01);
          } else {
            m.add_face(v00, v11, v10);
            m.add_face(v00, v01, v11);
          }
        }
  return m;
}

TEST(DecimateSimplify, SubdividedCubeBecomesTheCube) {
  const Mesh cube = subdivided_cube(6);
  ASSERT_EQ(cube.n_faces(), 6u * 72u);
  fest::decimate::SimplifyOptions o;
  o.target_faces = 12;
  fest::decimate::SimplifyStats st;
  const Mesh out = fest::decimate::simplify(cube, o, &st);
  EXPECT_LE(out.n_faces(), 24u);
  // Every collapse of a flat region or a straight edge is exact: the surface is unchanged.
  const auto d = fest::compare::surface_distance(cube, out, 20000);
  EXPECT_LT(d.hausdorff, 1e-9);
  const auto topo = fest::compare::mesh_topology(out);
  EXPECT_TRUE(topo.closed());
  EXPECT_TRUE(topo.manifold());
  EXPECT_EQ(topo.genus, 0);
}

TEST(DecimateSimplify, LockedFeaturesKeepEveryCubeEdgeVertex) {
  // All 12 cube edges are features (90 deg > 45 deg); with them locked only the face
  // interiors can go: 8 corners + 12 x 5 edge vertices = 68 vertices, and a closed genus-0
  // triangle mesh with V vertices has 2V - 4 = 132 faces.
  const Mesh cube = subdivided_cube(6);
  fest::decimate::SimplifyOptions o;
  o.target_faces = 12;
  o.feature_angle_deg = 45;
  o.lock_features = true;
  fest::decimate::SimplifyStats st;
  const Mesh out = fest::decimate::simplify(cube, o, &st);
  EXPECT_EQ(st.feature_edges, 12u * 6u);
  EXPECT_EQ(st.locked_vertices, 68u);
  EXPECT_EQ(out.n_vertices(), 68u);
  EXPECT_EQ(out.n_faces(), 132u);
  EXPECT_LT(fest::compare::surface_distance(cube, out, 20000).hausdorff, 1e-12);
}

TEST(DecimateSimplify, EveryWeightingKeepsTheCubeExact) {
  for (const auto w : {fest::decimate::Weighting::area, fest::decimate::Weighting::sqrt_area, fest::decimate::Weighting::uniform}) {
    const Mesh cube = subdivided_cube(4);
    fest::decimate::SimplifyOptions o;
    o.target_faces = 12;
    o.weighting = w;
    const Mesh out = fest::decimate::simplify(cube, o);
    EXPECT_LE(out.n_faces(), 24u);
    EXPECT_LT(fest::compare::surface_distance(cube, out, 20000).hausdorff, 1e-9);
  }
}

TEST(DecimateSimplify, LockedBoundaryOfASquareStaysPut) {
  // The top face of a subdivided cube, alone: an open square with a boundary.
  Mesh sq;
  const int n = 8;
  std::vector<Mesh::VertexHandle> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) v.push_back(sq.add_vertex(OpenMesh::Vec3d(double(i) / n, double(j) / n, 0.0)));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1], c = v[(j + 1) * (n + 1) + i + 1], d = v[(j + 1) * (n + 1) + i];
      sq.add_face(a, b, c);
      sq.add_face(a, c, d);
    }
  fest::decimate::SimplifyOptions o;
  o.target_faces = 2;
  o.lock_boundary = true;
  fest::decimate::SimplifyStats st;
  const Mesh out = fest::decimate::simplify(sq, o, &st);
  EXPECT_EQ(st.locked_vertices, 4u * n);
  // All interior vertices can go; the 32 boundary vertices stay and need 30 triangles.
  EXPECT_EQ(out.n_vertices(), 4u * n);
  EXPECT_EQ(out.n_faces(), 4u * n - 2);
  for (const auto u : out.vertices()) {
    const auto p = out.point(u);
    EXPECT_EQ(p[2], 0.0);
    const bool on_boundary = p[0] == 0 || p[0] == 1 || p[1] == 0 || p[1] == 1;
    EXPECT_TRUE(on_boundary);
  }
  const auto d = fest::compare::surface_distance(sq, out, 10000);
  EXPECT_LT(d.hausdorff, 1e-12);
}

TEST(DecimateSimplify, ErrorBoundZeroKeepsANoisySurface) {
  // A bumpy grid: with a zero error bound no collapse that moves the surface is taken.
  Mesh m;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> bump(-0.05, 0.05);
  const int n = 6;
  std::vector<Mesh::VertexHandle> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) v.push_back(m.add_vertex(OpenMesh::Vec3d(i, j, bump(rng))));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.add_face(v[j * (n + 1) + i], v[j * (n + 1) + i + 1], v[(j + 1) * (n + 1) + i + 1]);
      m.add_face(v[j * (n + 1) + i], v[(j + 1) * (n + 1) + i + 1], v[(j + 1) * (n + 1) + i]);
    }
  fest::decimate::SimplifyOptions o;
  o.max_error = 0.0;
  const Mesh out = fest::decimate::simplify(m, o);
  EXPECT_EQ(out.n_faces(), m.n_faces());
}

TEST(DecimateSimplify, NonFiniteInputIsBadInput) {
  Mesh m;
  const auto a = m.add_vertex(OpenMesh::Vec3d(0, 0, 0)), b = m.add_vertex(OpenMesh::Vec3d(1, 0, 0)),
             c = m.add_vertex(OpenMesh::Vec3d(0, std::nan(""), 0));
  m.add_face(a, b, c);
  fest::decimate::SimplifyOptions o;
  o.target_faces = 1;
  try {
    fest::decimate::simplify(m, o);
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
  }
}

TEST(DecimateSimplify, AttributesFollowTheOptimalPoint) {
  // Colours linear in x on a flat grid: after simplification each surviving vertex's
  // colour still matches the linear field at its (moved) position.
  Mesh m;
  m.request_vertex_colors();
  const int n = 10;
  std::vector<Mesh::VertexHandle> v;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      v.push_back(m.add_vertex(OpenMesh::Vec3d(double(i) / n, double(j) / n, 0)));
      m.set_color(v.back(), OpenMesh::Vec3uc(static_cast<unsigned char>(25 * i), 0, 0));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.add_face(v[j * (n + 1) + i], v[j * (n + 1) + i + 1], v[(j + 1) * (n + 1) + i + 1]);
      m.add_face(v[j * (n + 1) + i], v[(j + 1) * (n + 1) + i + 1], v[(j + 1) * (n + 1) + i]);
    }
  fest::decimate::SimplifyOptions o;
  o.target_faces = 20;
  const Mesh out = fest::decimate::simplify(m, o);
  ASSERT_TRUE(out.has_vertex_colors());
  for (const auto u : out.vertices()) EXPECT_NEAR(out.color(u)[0], 250.0 * out.point(u)[0], 1.0);
}

}  // namespace
