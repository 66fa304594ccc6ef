// The coarser-mesh reference (tin_reference.hpp) against the grid reference on the same
// surface: built from the finest triangulation of a DEM, the TIN *is* the grid's surface,
// so heights and exact overlay errors of any triangle must agree (docs/terrainlod.md §1).

#include <random>

#include <gtest/gtest.h>

#include "terrainlod/reference_surface.hpp"
#include "terrainlod/simplify.hpp"
#include "terrainlod/tin_reference.hpp"
#include "terrainlod/triangle_error.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using namespace fest::terrainlod;

TEST(TerrainlodTinReference, FinestTriangulationIsTheGridSurface) {
  const HeightGrid g = fest::test::fbm_grid(5, 11, 80.0);  // 33 x 33
  const ReferenceSurface grid(g, DiagonalRule::shortest);
  const Tin fine = finest_triangulation(g, DiagonalRule::shortest);
  const TinReference tin(fine.vertices, fine.triangles, 0, 0, g.width - 1, g.height - 1, 4);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, g.width - 1);
  for (int k = 0; k < 200; ++k) {
    const double x = u(rng), y = u(rng);
    EXPECT_NEAR(tin.height_at(x, y), grid.height_at(x, y), 1e-9) << x << ", " << y;
  }
  // Random lattice triangles with arbitrary (not sample) heights at their corners.
  std::uniform_int_distribution<int> c(0, g.width - 1);
  std::uniform_real_distribution<double> z(-50, 150);
  int measured = 0;
  while (measured < 300) {
    GridPoint a{double(c(rng)), double(c(rng)), z(rng)}, b{double(c(rng)), double(c(rng)), z(rng)},
        d{double(c(rng)), double(c(rng)), z(rng)};
    const double area = twice_area(a, b, d);
    if (area == 0) continue;
    if (area < 0) std::swap(b, d);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_NEAR(tin.triangle_error(a, b, d, inf), triangle_error(grid, a, b, d, inf), 1e-9);
    ++measured;
  }
}

TEST(TerrainlodTinReference, SimplifyingAgainstTheTinKeepsTheBound) {
  // The engine against a TIN reference made of the grid's finest triangulation: the
  // result is within the bound of the grid surface, measured independently.
  const HeightGrid g = fest::test::fbm_grid(5, 4, 80.0);
  const ReferenceSurface grid(g, DiagonalRule::shortest);
  const Tin fine = finest_triangulation(g, DiagonalRule::shortest);
  const TinReference tin(fine.vertices, fine.triangles, 0, 0, g.width - 1, g.height - 1, 4);
  std::vector<std::uint8_t> locked(fine.vertices.size(), 0);
  for (std::size_t i = 0; i < fine.vertices.size(); ++i) {
    const auto& p = fine.vertices[i];
    locked[i] = (p.x == 0 || p.y == 0 || p.x == g.width - 1 || p.y == g.height - 1) ? 1 : 0;
  }
  const SimplifyResult r = simplify_tin(tin, grid, fine, locked, 6.0, nullptr);
  EXPECT_LT(r.mesh.triangles.size(), fine.triangles.size() / 2);
  EXPECT_LE(tin_error(grid, r.mesh), 6.0 + 1e-9);
}

}  // namespace
