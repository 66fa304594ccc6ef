// DEM conditioning, the reference surface and the pyramid plan, from their definitions.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "terrainlod/height_grid.hpp"
#include "terrainlod/pyramid_plan.hpp"
#include "terrainlod/reference_surface.hpp"
#include "terrainlod/triangle_error.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using fest::terrainlod::HeightGrid;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(TerrainlodGrid, OneColumnIsBadInput) {
  HeightGrid g;
  g.width = 1;
  g.height = 5;
  g.h.assign(5, 1.0);
  fest::test::expect_bad_input([&] { fest::terrainlod::condition_grid(g); }, "1 column");
}

TEST(TerrainlodGrid, AllNodataIsBadInput) {
  HeightGrid g;
  g.width = g.height = 3;
  g.h.assign(9, kNaN);
  fest::test::expect_bad_input([&] { fest::terrainlod::condition_grid(g); }, "all samples are nodata");
}

TEST(TerrainlodGrid, NodataTakesTheNearestValidHeight) {
  HeightGrid g;
  g.width = 4;
  g.height = 1 + 1;
  g.h = {10, kNaN, kNaN, kNaN, 10, kNaN, kNaN, 40};
  const auto rep = fest::terrainlod::condition_grid(g);
  EXPECT_EQ(rep.nodata, 5u);
  EXPECT_EQ(rep.z_min, 10);
  EXPECT_EQ(rep.z_max, 40);
  // (1,0) is 1 step from (0,0)=10; (3,0) is 1 step from (3,1)=40; (1,1) from (0,1)=10;
  // (2,1) from (3,1)=40 (1 step); (2,0): 2 steps from both, the first to reach it wins
  // (breadth-first in scan order: (0,0)'s front arrives first).
  EXPECT_EQ(g.h[1], 10);
  EXPECT_EQ(g.h[3], 40);
  EXPECT_EQ(g.h[5], 10);
  EXPECT_EQ(g.h[6], 40);
  EXPECT_EQ(g.h[2], 10);
  EXPECT_EQ(g.valid[0], 1);
  EXPECT_EQ(g.valid[1], 0);
}

TEST(TerrainlodGrid, ReferenceInterpolatesTheChosenDiagonal) {
  HeightGrid g;
  g.width = g.height = 2;
  g.h = {0, 0, 0, 10};  // h(1,1) = 10: the SW-NE diagonal differs by 10, the other by 0
  const fest::terrainlod::ReferenceSurface shortest(g, fest::terrainlod::DiagonalRule::shortest);
  EXPECT_FALSE(shortest.ne_diagonal(0, 0));
  EXPECT_DOUBLE_EQ(shortest.height_at(0.5, 0.5), 0);     // on the NW-SE diagonal: 0
  EXPECT_DOUBLE_EQ(shortest.height_at(0.75, 0.75), 5);   // NE triangle: 10 (x + y - 1)
  const fest::terrainlod::ReferenceSurface ne(g, fest::terrainlod::DiagonalRule::ne);
  EXPECT_DOUBLE_EQ(ne.height_at(0.5, 0.5), 5);           // on the SW-NE diagonal: 10 x 0.5
  EXPECT_DOUBLE_EQ(ne.height_at(0.5, 0.25), 2.5);        // SE triangle: 10 y
}

TEST(TerrainlodGrid, TriangleErrorFindsTheWorstOverlayVertex) {
  // One cell with a 10 m bump at (1,1) split by the NW-SE diagonal; the flat triangle
  // (0,0),(2,0),(2,2) over the 3 x 3 grid misses the bump by exactly 10 at (1,1).
  HeightGrid g = fest::test::plane_grid(3, 3, 0, 0, 0);
  g.h[4] = 10;
  const fest::terrainlod::ReferenceSurface ref(g, fest::terrainlod::DiagonalRule::ne);
  const fest::terrainlod::GridPoint a{0, 0, 0}, b{2, 0, 0}, c{2, 2, 0};
  EXPECT_DOUBLE_EQ(fest::terrainlod::triangle_error(ref, a, b, c, 1e9), 10);
  // Triangle (0,0),(2,0),(1,1) with the bump as its apex: z = 10 y. Its edge (2,0)-(1,1)
  // crosses cell (1,0)'s SW-NE diagonal at (1.5, 0.5), where the reference is 0 (the cell's
  // SE triangle has heights 0, 0, 0) and the triangle 5: no sample lies there, only an
  // edge-diagonal crossing finds it.
  const fest::terrainlod::GridPoint apex{1, 1, 10};
  EXPECT_DOUBLE_EQ(fest::terrainlod::triangle_error(ref, a, b, apex, 1e9), 5);
}

TEST(TerrainlodPlan, LevelsAndBudgets) {
  fest::terrainlod::PyramidParams p;  // B = T = 64, f = 1
  const auto plan = fest::terrainlod::plan_pyramid(257, 200, 10, 10, p);
  ASSERT_EQ(plan.levels, 2);  // 256 cells = 64 x 2^2
  EXPECT_EQ(plan.padded, 257);
  ASSERT_EQ(plan.level.size(), 3u);
  EXPECT_DOUBLE_EQ(plan.level[0].eps, 256.0 * 10 / 64);  // S_0 / T
  EXPECT_DOUBLE_EQ(plan.level[1].eps, 128.0 * 10 / 64);  // halves per level
  EXPECT_DOUBLE_EQ(plan.level[1].bound, 4.0 / 3.0 * 20);
  EXPECT_DOUBLE_EQ(plan.level[2].eps, 0);
  EXPECT_EQ(plan.level[2].tiles_x, 4);
  EXPECT_EQ(plan.level[2].tiles_y, 4);  // 199 cells -> 4 tiles of 64
  EXPECT_EQ(plan.level[0].tiles_x, 1);
}

TEST(TerrainlodPlan, TileMustBeAPowerOfTwo) {
  fest::terrainlod::PyramidParams p;
  p.tile = 48;
  try {
    fest::terrainlod::plan_pyramid(100, 100, 1, 1, p);
    ADD_FAILURE() << "no error";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
    EXPECT_STREQ(e.what(), "tile size 48 is not a power of two between 4 and 4096");
  }
}

}  // namespace
