// The collapse engine against mathematics: a plane needs two triangles, and on fractal
// terrain the result stays within the bound by an exhaustive check that shares no code
// with the engine's error measure (terrainlod_exhaustive.hpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "terrainlod/simplify.hpp"
#include "terrainlod_exhaustive.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using fest::terrainlod::DiagonalRule;
using fest::terrainlod::HeightGrid;
using fest::terrainlod::SimplifyOptions;
using fest::terrainlod::Tin;

using fest::test::exhaustive_error;

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
