// lib/terrainlod/nodata_mask: the run-length mask round-trips, damaged sections are bad
// input, and the hole rule (a nodata sample in the closed triangle) agrees with a brute
// force point-in-triangle test in exact integer arithmetic.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "core/error.hpp"
#include "terrainlod/nodata_mask.hpp"

namespace {

using namespace fest::terrainlod;

HeightGrid grid_with(int w, int h, const std::function<bool(int, int)>& nodata) {
  HeightGrid g;
  g.width = w, g.height = h;
  g.h.assign(g.size(), 1.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      if (nodata(i, j)) g.h[static_cast<std::size_t>(j) * w + i] = NAN;
  condition_grid(g);
  return g;
}

TEST(NodataMask, RoundTripsAndAnswersLikeTheGrid) {
  const HeightGrid g = grid_with(37, 23, [](int i, int j) { return (i - 15) * (i - 15) + (j - 9) * (j - 9) < 40 || (i * 7 + j * 3) % 11 == 0; });
  const NodataMask m = nodata_mask(g);
  std::size_t count = 0;
  for (std::size_t k = 0; k < g.size(); ++k) count += !g.valid[k];
  EXPECT_EQ(m.samples, count);
  const NodataMask d = decode_nodata_mask(encode_nodata_mask(m));
  EXPECT_EQ(encode_nodata_mask(d), encode_nodata_mask(m));
  for (int j = 0; j < g.height + 3; ++j)
    for (int i = 0; i < g.width + 3; ++i) {
      // Beyond the last row or column the padding repeats the edge sample.
      const int ci = std::min(i, g.width - 1), cj = std::min(j, g.height - 1);
      EXPECT_EQ(d.at(i, j), !g.valid[static_cast<std::size_t>(cj) * g.width + ci]) << i << "," << j;
    }
}

TEST(NodataMask, ValidBoundsHoldEveryValidSample) {
  // Valid only in a tilted band: columns 5..30, rows 3..19, a hole inside too.
  const HeightGrid g = grid_with(37, 23, [](int i, int j) {
    return i < 5 || i > 30 || j < 3 || j > 19 || (i + j) % 9 == 0 || (i > 10 && i < 14);
  });
  int i0 = 99, j0 = 99, i1 = -1, j1 = -1;
  for (int j = 0; j < g.height; ++j)
    for (int i = 0; i < g.width; ++i)
      if (g.valid[static_cast<std::size_t>(j) * g.width + i]) i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
  std::array<int, 4> box{};
  ASSERT_TRUE(valid_bounds(nodata_mask(g), box));
  EXPECT_EQ(box, (std::array<int, 4>{i0, j0, i1, j1}));
  const HeightGrid none = grid_with(4, 4, [](int, int) { return false; });
  ASSERT_TRUE(valid_bounds(nodata_mask(none), box));
  EXPECT_EQ(box, (std::array<int, 4>{0, 0, 3, 3}));
}

TEST(NodataMask, DamagedSectionsAreBadInput) {
  const HeightGrid g = grid_with(8, 4, [](int i, int j) { return i == 2 && j == 1; });
  const std::string s = encode_nodata_mask(nodata_mask(g));
  EXPECT_NO_THROW(decode_nodata_mask(s));
  EXPECT_THROW(decode_nodata_mask("FTNX" + s.substr(4)), fest::Error);
  for (std::size_t n = 0; n < s.size(); ++n) EXPECT_THROW(decode_nodata_mask(s.substr(0, n)), fest::Error) << n;
  EXPECT_THROW(decode_nodata_mask(s + "x"), fest::Error);
  std::string wrong_count = s;
  wrong_count[13] = 5;
  EXPECT_THROW(decode_nodata_mask(wrong_count), fest::Error);
  std::string version = s;
  version[4] = 9;
  EXPECT_THROW(decode_nodata_mask(version), fest::Error);
}

// Exact: p in the closed triangle iff the three edge functions share a sign (or are 0).
bool contains(const std::array<std::array<std::int64_t, 2>, 3>& v, std::int64_t x, std::int64_t y) {
  auto side = [&](int a, int b) {
    return (v[b][0] - v[a][0]) * (y - v[a][1]) - (v[b][1] - v[a][1]) * (x - v[a][0]);
  };
  const std::int64_t s0 = side(0, 1), s1 = side(1, 2), s2 = side(2, 0);
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

TEST(NodataMask, RuleMatchesBruteForce) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const double density = 0.002 + 0.05 * (trial % 5);
    std::bernoulli_distribution hole(density);
    std::vector<char> nd(30 * 26);
    for (auto& c : nd) c = hole(rng);
    const HeightGrid g = grid_with(30, 26, [&](int i, int j) { return nd[static_cast<std::size_t>(j) * 30 + i] != 0; });
    const NodataMask m = nodata_mask(g);
    std::uniform_int_distribution<int> coord(0, 34);  // some beyond the grid: the padding
    for (int t = 0; t < 300; ++t) {
      std::array<std::array<std::int64_t, 2>, 3> v;
      for (auto& p : v) p = {coord(rng), coord(rng)};
      if ((v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0]) == 0) continue;
      bool expect = false;
      for (std::int64_t y = 0; y <= 34 && !expect; ++y)
        for (std::int64_t x = 0; x <= 34 && !expect; ++x)
          expect = contains(v, x, y) && m.at(x, y);
      EXPECT_EQ(covers_nodata(m, v), expect) << trial << " " << t;
    }
  }
}

TEST(NodataMask, CutHolesKeepsOnlyTrianglesClearOfNodataAndTheirVertices) {
  const HeightGrid g = grid_with(3, 3, [](int i, int j) { return i == 2 && j == 2; });
  const NodataMask m = nodata_mask(g);
  TileTriangulation tri;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) tri.vertices.push_back({i, j, static_cast<double>(10 * j + i)});
  // Two cells' worth: (0,0)-(1,1) split, and (1,1)-(2,2) split; the latter touches (2,2).
  tri.triangles = {{0, 1, 4}, {0, 4, 3}, {4, 5, 8}, {4, 8, 7}};
  EXPECT_EQ(cut_holes(m, tri), 2u);
  ASSERT_EQ(tri.triangles.size(), 2u);
  ASSERT_EQ(tri.vertices.size(), 4u);
  EXPECT_EQ(tri.vertices[2].z, 10.0);  // (0, 1): the kept vertices keep their order
  EXPECT_EQ(tri.triangles[1], (std::array<int, 3>{0, 3, 2}));
}

}  // namespace
