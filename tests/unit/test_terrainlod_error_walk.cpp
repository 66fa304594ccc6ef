// The fast exact error walks (triangle_error.cpp: the edge crossings with hoisted grid
// access, the triangle's rows stepped by exact integer edge crossings) against the plain
// definitions they replace, written out here: every sample in the triangle found by its
// three edge functions, and every crossing of an edge with the four line families found
// by its parameter and interpolated from the grid with std::floor. The fast walks must
// give the same numbers bit for bit (the engine's greedy order depends on exact ties), and
// the same "above the stop" answers.

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "terrainlod/reference_surface.hpp"
#include "terrainlod/triangle_error.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using fest::terrainlod::DiagonalRule;
using fest::terrainlod::GridPoint;
using fest::terrainlod::ReferenceSurface;
using fest::terrainlod::twice_area;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Samples inside or on the triangle, each decided by the three edge functions; inner
// samples on the plane gx x + gy y + g0, samples on an edge by barycentric weights (the
// same two formulas the walk uses for the two kinds of sample).
double samples_definition(const ReferenceSurface& ref, const GridPoint& a, const GridPoint& b, const GridPoint& c) {
  const double d = twice_area(a, b, c);
  const double gx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / d;
  const double gy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / d;
  const double g0 = a.z - gx * a.x - gy * a.y;
  double worst = 0;
  for (int j = 0; j < ref.height(); ++j) {
    // The span's end samples of a row use the barycentric form, the rest the plane.
    int first = -1, last = -1;
    for (int i = 0; i < ref.width(); ++i) {
      const GridPoint p{double(i), double(j), 0};
      if (twice_area(p, b, c) >= 0 && twice_area(a, p, c) >= 0 && twice_area(a, b, p) >= 0) {
        if (first < 0) first = i;
        last = i;
      }
    }
    if (first < 0) continue;
    for (int i = first; i <= last; ++i) {
      const GridPoint p{double(i), double(j), 0};
      const double wa = twice_area(p, b, c), wb = twice_area(a, p, c), wc = twice_area(a, b, p);
      const double z = (i == first || i == last) ? (wa * a.z + wb * b.z + wc * c.z) / d : gx * i + (gy * j + g0);
      worst = std::max(worst, std::abs(z - ref.sample(i, j)));
    }
  }
  return worst;
}

// Crossings of p -> q with x = k, y = k, x + y = k (where the cell has the NW-SE
// diagonal) and x - y = k (SW-NE), the reference interpolated along the crossed line.
double edge_definition(const ReferenceSurface& ref, const GridPoint& p, const GridPoint& q) {
  double worst = 0;
  auto cx = [&](double x) { return std::clamp(static_cast<int>(std::floor(x)), 0, ref.width() - 2); };
  auto cy = [&](double y) { return std::clamp(static_cast<int>(std::floor(y)), 0, ref.height() - 2); };
  for (int f = 0; f < 4; ++f) {
    auto s = [f](const GridPoint& g) { return f == 0 ? g.x : f == 1 ? g.y : f == 2 ? g.x + g.y : g.x - g.y; };
    const double sp = s(p), sq = s(q);
    if (sp == sq) continue;
    const double inv = 1 / (sq - sp);
    for (double k = std::floor(std::min(sp, sq)) + 1; k < std::max(sp, sq); k += 1) {
      const double t = (k - sp) * inv;
      const double x = p.x + t * (q.x - p.x), y = p.y + t * (q.y - p.y);
      double r;
      if (f == 0) {
        const int i = static_cast<int>(k), j = cy(y);
        r = ref.sample(i, j) + (y - j) * (ref.sample(i, j + 1) - ref.sample(i, j));
      } else if (f == 1) {
        const int j = static_cast<int>(k), i = cx(x);
        r = ref.sample(i, j) + (x - i) * (ref.sample(i + 1, j) - ref.sample(i, j));
      } else if (f == 2) {
        const int i = cx(x), j = static_cast<int>(k) - 1 - i;
        if (j < 0 || j > ref.height() - 2 || ref.ne_diagonal(i, j)) continue;
        r = ref.sample(i, j + 1) + (x - i) * (ref.sample(i + 1, j) - ref.sample(i, j + 1));
      } else {
        const int i = cx(x), j = i - static_cast<int>(k);
        if (j < 0 || j > ref.height() - 2 || !ref.ne_diagonal(i, j)) continue;
        r = ref.sample(i, j) + (x - i) * (ref.sample(i + 1, j + 1) - ref.sample(i, j));
      }
      worst = std::max(worst, std::abs(p.z + t * (q.z - p.z) - r));
    }
  }
  return worst;
}

class TerrainlodErrorWalk : public ::testing::TestWithParam<DiagonalRule> {};

TEST_P(TerrainlodErrorWalk, SameNumbersAsTheDefinitionsBitForBit) {
  const auto grid = fest::test::fbm_grid(5, 11);  // 33 x 33, non-integer heights
  const ReferenceSurface ref(grid, GetParam());
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coord(0, grid.width - 1);
  auto point = [&] {
    const int i = coord(rng), j = coord(rng);
    return GridPoint{double(i), double(j), grid.at(i, j) + (rng() % 7) * 0.25};
  };
  int triangles = 0, early = 0;
  while (triangles < 2000) {
    GridPoint a = point(), b = point(), c = point();
    if (rng() % 4 == 0) b.y = a.y;  // horizontal edges
    if (rng() % 4 == 0) c.x = b.x;  // vertical edges
    b.z = grid.at(static_cast<int>(b.x), static_cast<int>(b.y));
    c.z = grid.at(static_cast<int>(c.x), static_cast<int>(c.y));
    if (twice_area(a, b, c) < 0) std::swap(b, c);
    if (twice_area(a, b, c) <= 0) continue;
    ++triangles;
    const double s = samples_definition(ref, a, b, c);
    ASSERT_EQ(fest::terrainlod::triangle_samples_error(ref, a, b, c, kInf), s);
    for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
      ASSERT_EQ(fest::terrainlod::edge_error(ref, p, q, kInf), edge_definition(ref, p, q));
    // With a stop: above it exactly when the definition is, the exact value otherwise.
    const double stop = s * (rng() % 3) / 2;
    const double e = fest::terrainlod::triangle_samples_error(ref, a, b, c, stop);
    if (s > stop) {
      EXPECT_GT(e, stop);
      ++early;
    } else {
      EXPECT_EQ(e, s);
    }
  }
  EXPECT_GT(early, 200);
}

TEST_P(TerrainlodErrorWalk, AxisEdgesEverywhereSameAsTheDefinition) {
  // Horizontal and vertical edges of every length up to 9 from every sample, both
  // directions, end heights off the surface: the walk skips the diagonal families on some
  // of them (they repeat the grid line crossings), never changing a bit.
  const auto grid = fest::test::fbm_grid(4, 5);  // 17 x 17
  const ReferenceSurface ref(grid, GetParam());
  int edges = 0;
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i)
      for (int len = 1; len <= 9; ++len)
        for (int dir = 0; dir < 4; ++dir) {
          const int di = dir == 0 ? len : dir == 1 ? -len : 0, dj = dir == 2 ? len : dir == 3 ? -len : 0;
          const int i2 = i + di, j2 = j + dj;
          if (i2 < 0 || j2 < 0 || i2 >= grid.width || j2 >= grid.height) continue;
          const GridPoint p{double(i), double(j), grid.at(i, j) + 0.3 * len};
          const GridPoint q{double(i2), double(j2), grid.at(i2, j2) - 0.7};
          ASSERT_EQ(fest::terrainlod::edge_error(ref, p, q, kInf), edge_definition(ref, p, q))
              << i << "," << j << " -> " << i2 << "," << j2;
          ++edges;
        }
  EXPECT_GT(edges, 3000);
}

INSTANTIATE_TEST_SUITE_P(DiagonalRules, TerrainlodErrorWalk,
                         ::testing::Values(DiagonalRule::shortest, DiagonalRule::alternate, DiagonalRule::ne),
                         [](const ::testing::TestParamInfo<DiagonalRule>& rule) {
                           return rule.param == DiagonalRule::shortest    ? std::string("shortest")
                                  : rule.param == DiagonalRule::alternate ? std::string("alternate")
                                                                          : std::string("ne");
                         });

}  // namespace
