// The RTIN start mesh (lib/terrainlod/rtin_start.hpp) against its contract: it covers the
// lattice's square with counter-clockwise triangles, it is conforming (every edge is shared
// by two triangles in opposite directions or lies on the square's boundary: no
// T-junctions), every locked lattice point is a vertex, and every triangle (with its
// transition variants, where a tile frame is given) is within the limit by the exhaustive
// check of terrainlod_exhaustive.hpp, which shares no code with the library's measure.

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "terrainlod/rtin_start.hpp"
#include "terrainlod/simplify.hpp"
#include "terrainlod/transition.hpp"
#include "terrainlod_exhaustive.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using namespace fest::terrainlod;

std::vector<std::uint8_t> border_points(int n) {
  std::vector<std::uint8_t> f(static_cast<std::size_t>(n + 1) * (n + 1), 0);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (i == 0 || j == 0 || i == n || j == n) f[static_cast<std::size_t>(j) * (n + 1) + i] = 1;
  return f;
}

std::vector<std::uint8_t> corner_points(int n) {
  std::vector<std::uint8_t> f(static_cast<std::size_t>(n + 1) * (n + 1), 0);
  for (std::size_t k : {std::size_t{0}, std::size_t(n), std::size_t(n) * (n + 1), std::size_t(n + 1) * (n + 1) - 1}) f[k] = 1;
  return f;
}

TriangleMeasure grid_measure(const ReferenceSurface& ref) {
  return [&ref](const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) {
    return triangle_error(ref, a, b, c, s);
  };
}

// Coverage, orientation, conformity, vertices on the lattice, locked points present.
void expect_conforming_cover(const RtinStart& r, const SquareLattice& lat, const std::vector<std::uint8_t>& locked) {
  const double side = double(lat.n) * lat.step;
  double area = 0;
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : r.tin.triangles) {
    const double d = twice_area(r.tin.vertices[t[0]], r.tin.vertices[t[1]], r.tin.vertices[t[2]]);
    EXPECT_GT(d, 0) << "counter-clockwise, positive area";
    area += d / 2;
    for (int e = 0; e < 3; ++e) {
      const int uses = ++directed[std::make_pair(t[e], t[(e + 1) % 3])];
      EXPECT_EQ(uses, 1) << "an edge used twice in one direction";
    }
  }
  EXPECT_DOUBLE_EQ(area, side * side);
  auto on_boundary = [&](const GridPoint& p, const GridPoint& q) {
    return (p.x == lat.x0 && q.x == lat.x0) || (p.x == lat.x0 + side && q.x == lat.x0 + side) ||
           (p.y == lat.y0 && q.y == lat.y0) || (p.y == lat.y0 + side && q.y == lat.y0 + side);
  };
  for (const auto& [e, k] : directed) {
    if (!directed.count({e.second, e.first})) {
      EXPECT_TRUE(on_boundary(r.tin.vertices[e.first], r.tin.vertices[e.second]))
          << "an interior edge with one triangle: a T-junction";
    }
  }
  ASSERT_EQ(r.locked.size(), r.tin.vertices.size());
  std::set<std::pair<int, int>> present;
  for (std::size_t v = 0; v < r.tin.vertices.size(); ++v) {
    const auto& p = r.tin.vertices[v];
    const int i = (static_cast<int>(p.x) - lat.x0) / lat.step, j = (static_cast<int>(p.y) - lat.y0) / lat.step;
    EXPECT_EQ(lat.x0 + i * lat.step, p.x);
    EXPECT_EQ(lat.y0 + j * lat.step, p.y);
    EXPECT_TRUE(present.insert({i, j}).second) << "one vertex per lattice point";
    EXPECT_EQ(r.locked[v], locked[static_cast<std::size_t>(j) * (lat.n + 1) + i]);
  }
  for (int j = 0; j <= lat.n; ++j)
    for (int i = 0; i <= lat.n; ++i) {
      if (locked[static_cast<std::size_t>(j) * (lat.n + 1) + i]) {
        EXPECT_TRUE(present.count({i, j})) << i << "," << j;
      }
    }
}

TEST(TerrainlodRtin, PlaneIsTheTwoHalfSquares) {
  const HeightGrid g = fest::test::plane_grid(17, 17, 0.75, -2.5, 100);
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  const SquareLattice lat{0, 0, 16, 1};
  const auto r = rtin_start_mesh(ref, lat, corner_points(16), 0, grid_measure(ref));
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->tin.triangles.size(), 2u);
  EXPECT_EQ(r->tin.vertices.size(), 4u);
  expect_conforming_cover(*r, lat, corner_points(16));
}

TEST(TerrainlodRtin, LockedBorderOfAPlaneIsConforming) {
  const HeightGrid g = fest::test::plane_grid(33, 33, 1, 2, 3);
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  for (int n : {1, 2, 4, 8, 16, 32}) {
    const SquareLattice lat{0, 0, n, 32 / n};
    const auto r = rtin_start_mesh(ref, lat, border_points(n), 1e-9, grid_measure(ref));
    ASSERT_TRUE(r.has_value());
    expect_conforming_cover(*r, lat, border_points(n));
    // Every triangle of a plane is exact: the two half-squares stay, fanned to the border
    // points, and no interior point is a vertex: a polygon of 4n corners, 4n - 2 triangles.
    EXPECT_EQ(r->tin.vertices.size(), 4u * n) << "n " << n;
    EXPECT_EQ(r->tin.triangles.size(), 4u * n - 2) << "n " << n;
  }
}

TEST(TerrainlodRtin, FbmWithinTheLimitByExhaustiveCheck) {
  const HeightGrid g = fest::test::fbm_grid(6, 5);  // 65 x 65, integer heights
  for (auto rule : {DiagonalRule::shortest, DiagonalRule::ne}) {
    const ReferenceSurface ref(g, rule);
    for (int n : {64, 32}) {
      const SquareLattice lat{0, 0, n, 64 / n};
      for (double limit : {0.5, 2.0, 8.0, 30.0}) {
        for (const auto& locked : {border_points(n), corner_points(n)}) {
          const auto r = rtin_start_mesh(ref, lat, locked, limit, grid_measure(ref));
          // On the full grid every cell fits with the surface's own diagonal (error 0).
          if (n == 64) {
            ASSERT_TRUE(r.has_value());
          }
          if (!r) continue;
          expect_conforming_cover(*r, lat, locked);
          for (const auto& t : r->tin.triangles) {
            EXPECT_LE(fest::test::exhaustive_triangle_error(g, r->tin.vertices[t[0]], r->tin.vertices[t[1]],
                                                            r->tin.vertices[t[2]], rule),
                      limit + 1e-9)
                << "n " << n << " limit " << limit;
          }
          if (limit >= 8) {
            EXPECT_LT(r->tin.triangles.size(), std::size_t(n) * n) << "adaptive: under half the lattice";
          }
        }
      }
    }
  }
}

TEST(TerrainlodRtin, CellsTakeTheOtherDiagonalWhereTheRtinsDoesNotFit) {
  // Integer fBm at half a height unit: a cell whose RTIN diagonal is not the surface's
  // misses by |h00 + h11 - h10 - h01| / 2, at least 1/2 wherever the two differ.
  const HeightGrid g = fest::test::fbm_grid(5, 9);
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  const SquareLattice lat{0, 0, 32, 1};
  const auto r = rtin_start_mesh(ref, lat, border_points(32), 0.25, grid_measure(ref));
  ASSERT_TRUE(r.has_value());
  EXPECT_GT(r->flipped_cells, 0u);
  expect_conforming_cover(*r, lat, border_points(32));
  EXPECT_LE(fest::test::exhaustive_error(g, r->tin, DiagonalRule::shortest), 0.25);
}

TEST(TerrainlodRtin, TransitionVariantsWithinTheLimit) {
  // A tile of 64 cells on a lattice of step 2, its finer neighbours' border points every
  // cell on all four sides: every triangle in every variant is within the limit.
  const HeightGrid g = fest::test::fbm_grid(7, 4, 60.0);  // 129 x 129
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  TileFrame frame;
  frame.x0 = 32, frame.y0 = 64, frame.x1 = 96, frame.y1 = 128;
  frame.fine_step = 1;
  frame.refinable = 15;
  const SquareLattice lat{32, 64, 32, 2};
  const TriangleMeasure measure = [&](const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) {
    return transition_error(ref, frame, a, b, c, s);
  };
  for (double limit : {4.0, 12.0}) {
    const auto r = rtin_start_mesh(ref, lat, border_points(32), limit, measure);
    ASSERT_TRUE(r.has_value()) << "limit " << limit;
    expect_conforming_cover(*r, lat, border_points(32));
    std::size_t variants = 0;
    for (const auto& t : r->tin.triangles) {
      const GridPoint &a = r->tin.vertices[t[0]], &b = r->tin.vertices[t[1]], &c = r->tin.vertices[t[2]];
      std::vector<GridPoint> extra;
      const auto inserts = border_inserts(ref, frame, a, b, c, extra);
      auto point = [&](int id) -> const GridPoint& { return id == 0 ? a : id == 1 ? b : id == 2 ? c : extra[id - 3]; };
      for (unsigned m = 0; m < 16; ++m) {
        std::vector<std::array<int, 3>> pieces;
        refine_triangle({0, 1, 2}, inserts, m, pieces);
        variants += pieces.size();
        for (const auto& q : pieces) {
          EXPECT_LE(fest::test::exhaustive_triangle_error(g, point(q[0]), point(q[1]), point(q[2]), DiagonalRule::shortest),
                    limit + 1e-9);
        }
      }
    }
    EXPECT_GT(variants, 16 * r->tin.triangles.size()) << "border triangles were split";
  }
}

TEST(TerrainlodRtin, LowerBoundOnlyRejects) {
  // The edge-midpoint lower bound skips exact measurements of triangles that are over
  // anyway: the same mesh with and without it, grid and transition measures alike.
  const HeightGrid g = fest::test::fbm_grid(7, 6, 60.0);
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  const PointHeight height = [&ref](double x, double y) { return ref.height_at(x, y); };
  TileFrame frame;
  frame.x0 = 0, frame.y0 = 0, frame.x1 = 128, frame.y1 = 128;
  frame.fine_step = 1;
  frame.refinable = 15;
  const TriangleMeasure with_variants = [&](const GridPoint& a, const GridPoint& b, const GridPoint& c, double s) {
    return transition_error(ref, frame, a, b, c, s);
  };
  const SquareLattice lat{0, 0, 64, 2};
  for (const TriangleMeasure& measure : {grid_measure(ref), with_variants})
    for (double limit : {3.0, 10.0}) {
      const auto plain = rtin_start_mesh(ref, lat, border_points(64), limit, measure);
      const auto bounded = rtin_start_mesh(ref, lat, border_points(64), limit, measure, height);
      ASSERT_TRUE(plain && bounded);
      EXPECT_EQ(plain->tin.triangles, bounded->tin.triangles);
      ASSERT_EQ(plain->tin.vertices.size(), bounded->tin.vertices.size());
      for (std::size_t v = 0; v < plain->tin.vertices.size(); ++v) {
        EXPECT_EQ(plain->tin.vertices[v].x, bounded->tin.vertices[v].x);
        EXPECT_EQ(plain->tin.vertices[v].y, bounded->tin.vertices[v].y);
      }
      EXPECT_EQ(plain->rejected, 0u);
      EXPECT_GT(bounded->rejected, 0u);
      EXPECT_LT(bounded->measured, plain->measured);
    }
}

TEST(TerrainlodRtin, NoStartMeshWhereNeitherDiagonalFits) {
  // A spike at the centre of the only lattice cell (step 2): both diagonals miss it by 10.
  HeightGrid g = fest::test::plane_grid(3, 3, 0, 0, 0);
  g.h[4] = 10;
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  EXPECT_FALSE(rtin_start_mesh(ref, SquareLattice{0, 0, 1, 2}, corner_points(1), 1, grid_measure(ref)).has_value());
  EXPECT_TRUE(rtin_start_mesh(ref, SquareLattice{0, 0, 1, 2}, corner_points(1), 10, grid_measure(ref)).has_value());
}

TEST(TerrainlodRtin, BadLatticeIsAUsageError) {
  const HeightGrid g = fest::test::plane_grid(9, 9, 0, 0, 0);
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  std::vector<std::uint8_t> interior = border_points(8);
  interior[4 * 9 + 4] = 1;
  const std::pair<SquareLattice, std::vector<std::uint8_t>> bad[] = {
      {SquareLattice{0, 0, 3, 1}, border_points(3)},  // not a power of two
      {SquareLattice{0, 0, 8, 2}, border_points(8)},  // beyond the DEM
      {SquareLattice{4, 0, 8, 1}, border_points(8)},
      {SquareLattice{0, 0, 8, 1}, border_points(4)},  // flags for another lattice
      {SquareLattice{0, 0, 8, 1}, interior},          // a locked point off the border
  };
  for (const auto& [lat, locked] : bad) {
    try {
      rtin_start_mesh(ref, lat, locked, 1, grid_measure(ref));
      ADD_FAILURE() << "no error for n " << lat.n;
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::usage);
    }
  }
}

TEST(TerrainlodRtin, EngineFromEitherStartKeepsTheBound) {
  const HeightGrid g = fest::test::fbm_grid(6, 12);
  for (double eps : {2.0, 10.0}) {
    std::size_t triangles[2] = {0, 0};
    for (StartRule start : {StartRule::lattice, StartRule::rtin}) {
      SimplifyOptions o;
      o.max_error = eps;
      o.start = start;
      const auto r = simplify_grid(g, o);
      EXPECT_LE(fest::test::exhaustive_error(g, r.mesh, DiagonalRule::shortest), eps + r.tolerance);
      triangles[start == StartRule::rtin] = r.mesh.triangles.size();
    }
    // Both are greedy decimations to the same bound: neither is far from the other.
    EXPECT_LT(triangles[1], 2 * triangles[0]);
    EXPECT_LT(triangles[0], 2 * triangles[1]);
  }
}

}  // namespace
