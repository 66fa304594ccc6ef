// The collapse engine against mathematics: a plane needs two triangles, and on fractal
// terrain the result stays within the bound by an exhaustive check that shares no code
// with the engine's error measure (polygon clipping of every reference triangle against
// every overlapping result triangle; the difference of two linear functions on a convex
// polygon is largest at a polygon corner).

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "terrainlod/simplify.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using fest::terrainlod::DiagonalRule;
using fest::terrainlod::HeightGrid;
using fest::terrainlod::SimplifyOptions;
using fest::terrainlod::Tin;

struct P {
  double x, y;
};

double cross(P o, P a, P b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Sutherland-Hodgman: polygon clipped by the half-plane left of a -> b (ccw triangle).
std::vector<P> clip(const std::vector<P>& poly, P a, P b) {
  std::vector<P> out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const P p = poly[k], q = poly[(k + 1) % poly.size()];
    const double dp = cross(a, b, p), dq = cross(a, b, q);
    if (dp >= 0) out.push_back(p);
    if ((dp >= 0) != (dq >= 0)) {
      const double t = dp / (dp - dq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}

// Linear interpolation of z over a triangle at (x, y) by barycentric coordinates.
double lerp3(const std::array<P, 3>& t, const std::array<double, 3>& z, P p) {
  const double d = cross(t[0], t[1], t[2]);
  return (cross(p, t[1], t[2]) * z[0] + cross(t[0], p, t[2]) * z[1] + cross(t[0], t[1], p) * z[2]) / d;
}

// The reference triangles of the grid with the diagonal rule re-derived here.
bool ne_cell(const HeightGrid& g, int i, int j, DiagonalRule rule) {
  if (rule == DiagonalRule::ne) return true;
  if (rule == DiagonalRule::alternate) return (i + j) % 2 == 0;
  return std::abs(g.at(i + 1, j + 1) - g.at(i, j)) <= std::abs(g.at(i, j + 1) - g.at(i + 1, j));
}

double exhaustive_error(const HeightGrid& g, const Tin& tin, DiagonalRule rule) {
  double worst = 0;
  for (const auto& tri : tin.triangles) {
    const auto& a = tin.vertices[tri[0]];
    const auto& b = tin.vertices[tri[1]];
    const auto& c = tin.vertices[tri[2]];
    const std::array<P, 3> T{P{a.x, a.y}, P{b.x, b.y}, P{c.x, c.y}};
    const std::array<double, 3> Tz{a.z, b.z, c.z};
    const int i0 = static_cast<int>(std::min({a.x, b.x, c.x})), i1 = static_cast<int>(std::max({a.x, b.x, c.x}));
    const int j0 = static_cast<int>(std::min({a.y, b.y, c.y})), j1 = static_cast<int>(std::max({a.y, b.y, c.y}));
    for (int j = j0; j < std::min(j1, g.height - 1); ++j)
      for (int i = i0; i < std::min(i1, g.width - 1); ++i) {
        const P p00{double(i), double(j)}, p10{i + 1.0, double(j)}, p01{double(i), j + 1.0}, p11{i + 1.0, j + 1.0};
        const double h00 = g.at(i, j), h10 = g.at(i + 1, j), h01 = g.at(i, j + 1), h11 = g.at(i + 1, j + 1);
        std::vector<std::pair<std::array<P, 3>, std::array<double, 3>>> refs;
        if (ne_cell(g, i, j, rule)) {
          refs.push_back({{p00, p10, p11}, {h00, h10, h11}});
          refs.push_back({{p00, p11, p01}, {h00, h11, h01}});
        } else {
          refs.push_back({{p00, p10, p01}, {h00, h10, h01}});
          refs.push_back({{p10, p11, p01}, {h10, h11, h01}});
        }
        for (const auto& [R, Rz] : refs) {
          std::vector<P> poly(R.begin(), R.end());
          for (int e = 0; e < 3 && !poly.empty(); ++e) poly = clip(poly, T[e], T[(e + 1) % 3]);
          for (const P& p : poly) worst = std::max(worst, std::abs(lerp3(T, Tz, p) - lerp3(R, Rz, p)));
        }
      }
  }
  return worst;
}

// Every triangle counter-clockwise with positive area, and together they cover the grid.
void expect_valid_cover(const HeightGrid& g, const Tin& tin) {
  double area = 0;
  for (const auto& t : tin.triangles) {
    const auto& a = tin.vertices[t[0]];
    const auto& b = tin.vertices[t[1]];
    const auto& c = tin.vertices[t[2]];
    const double d = fest::terrainlod::twice_area(a, b, c);
    EXPECT_GT(d, 0.5);
    area += d / 2;
  }
  EXPECT_DOUBLE_EQ(area, double(g.width - 1) * (g.height - 1));
}

TEST(TerrainlodSimplify, TiltedPlaneBecomesTwoTriangles) {
  for (auto rule : {DiagonalRule::shortest, DiagonalRule::alternate, DiagonalRule::ne}) {
    const HeightGrid g = fest::test::plane_grid(33, 17, 0.75, -2.5, 100);
    SimplifyOptions o;
    o.max_error = 0;
    o.diagonal = rule;
    const auto r = fest::terrainlod::simplify_grid(g, o);
    EXPECT_EQ(r.mesh.triangles.size(), 2u);
    EXPECT_EQ(r.mesh.vertices.size(), 4u);
    EXPECT_EQ(r.collapses, 33u * 17u - 4u);
    expect_valid_cover(g, r.mesh);
  }
}

TEST(TerrainlodSimplify, FbmWithinTheBoundByExhaustiveCheck) {
  const HeightGrid g = fest::test::fbm_grid(5, 7);  // 33 x 33
  for (double eps : {0.0, 1.0, 4.0, 15.0}) {
    for (auto rule : {DiagonalRule::shortest, DiagonalRule::ne}) {
      SimplifyOptions o;
      o.max_error = eps;
      o.diagonal = rule;
      const auto r = fest::terrainlod::simplify_grid(g, o);
      expect_valid_cover(g, r.mesh);
      const double err = exhaustive_error(g, r.mesh, rule);
      EXPECT_LE(err, eps + r.tolerance) << "eps " << eps;
      // The engine's own measure of the final mesh agrees with the independent one.
      const fest::terrainlod::ReferenceSurface ref(g, rule);
      EXPECT_NEAR(fest::terrainlod::tin_error(ref, r.mesh), err, 1e-9) << "eps " << eps;
      EXPECT_LT(r.mesh.triangles.size(), 2u * 32u * 32u);
    }
  }
}

TEST(TerrainlodSimplify, LargerBoundNeverKeepsTheFinestMesh) {
  const HeightGrid g = fest::test::fbm_grid(5, 11);
  SimplifyOptions o;
  o.max_error = 1000;  // above the height range: everything goes but the corners
  const auto r = fest::terrainlod::simplify_grid(g, o);
  EXPECT_EQ(r.mesh.vertices.size(), 4u);
  EXPECT_EQ(r.mesh.triangles.size(), 2u);
}

TEST(TerrainlodSimplify, NegativeBoundIsAUsageError) {
  const HeightGrid g = fest::test::plane_grid(3, 3, 0, 0, 0);
  SimplifyOptions o;
  o.max_error = -1;
  try {
    fest::terrainlod::simplify_grid(g, o);
    ADD_FAILURE() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
  }
}

}  // namespace
