// The pyramid against the spec's guarantees (terrainlod section 5): every tile and every
// one of its 16 transition triangulations within eps_l of the DEM (re-measured here on
// the decoded tile, not taken from the builder), decoding reproduces the encoder's
// triangles exactly, and tiles meet without cracks or T-junctions: along every shared
// border the two sides have the same vertices and edges, bit for bit.

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "terrainlod/pyramid_build.hpp"
#include "terrainlod/tile_codec.hpp"
#include "terrainlod/transition.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using namespace fest::terrainlod;
using Vertex = TileTriangulation::Vertex;
using Edge = std::pair<Vertex, Vertex>;

Pyramid make_pyramid(double cell) {
  HeightGrid g = fest::test::fbm_grid(7, 3, 60.0);  // 129 x 129, B = 16: L = 3
  BuildParams p;
  p.pyramid.tile = 16;
  p.threads = 2;
  return build_pyramid(g, cell, cell, p);
}

// 4 m cells: one texel (2^(L-l) cells) holds the terrain's detail at every level.
const Pyramid& fbm_pyramid() {
  static const Pyramid pyr = make_pyramid(4.0);
  return pyr;
}

// Every tile decoded from its bytes, every mask, re-measured against the DEM.
void expect_within_eps(const Pyramid& p) {
  HeightGrid g = fest::test::fbm_grid(7, 3, 60.0);
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  for (const auto& tile : p.tiles) {
    const Tile d = decode_tile(encode_tile(tile));
    const auto& lv = p.level[static_cast<std::size_t>(tile.id.level)];
    for (unsigned m = 0; m < 16; ++m) {
      const double e = triangulation_error(ref, triangulate(d, m, p.geometry(tile.id.level)));
      // Leaves (eps 0) are the DEM up to integer heights: exact.
      EXPECT_LE(e, lv.eps + 1e-9) << "tile " << tile.id.level << "/" << tile.id.x << "/" << tile.id.y << " mask " << m;
    }
  }
}

std::set<std::array<Vertex, 3>> triangle_set(const TileTriangulation& t) {
  std::set<std::array<Vertex, 3>> out;
  for (const auto& tri : t.triangles) {
    std::array<Vertex, 3> v{t.vertices[tri[0]], t.vertices[tri[1]], t.vertices[tri[2]]};
    // Rotation-invariant but orientation-keeping: start at the smallest vertex.
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    out.insert(v);
  }
  return out;
}

// Edges of the triangulation that lie on the line x = c (vertical) or y = c, each used by
// exactly one triangle, undirected.
std::set<Edge> border_edges(const TileTriangulation& t, bool vertical, std::int64_t c) {
  std::map<Edge, int> count;
  for (const auto& tri : t.triangles)
    for (int e = 0; e < 3; ++e) {
      Vertex a = t.vertices[tri[e]], b = t.vertices[tri[(e + 1) % 3]];
      if (b < a) std::swap(a, b);
      ++count[{a, b}];
    }
  std::set<Edge> out;
  for (const auto& [e, k] : count)
    if (k == 1 && (vertical ? (e.first.gx == c && e.second.gx == c) : (e.first.gy == c && e.second.gy == c)))
      out.insert(e);
  return out;
}

const Tile* find(const Pyramid& p, int l, int x, int y) {
  for (const auto& t : p.tiles)
    if (t.id == TileId{l, x, y}) return &t;
  return nullptr;
}

TEST(TerrainlodTransition, CornerTriangleSplitsInBorderOrder) {
  // Triangle 0 (0,0) 1 (2,0) 2 (0,2); edge 0->1 on the south border with point 3 (1,0),
  // edge 2->0 on the west border with point 4 (0,1).
  std::array<EdgeInsert, 3> ins;
  ins[0] = {kSouth, {3}};
  ins[2] = {kWest, {4}};
  std::vector<std::array<int, 3>> out;
  refine_triangle({0, 1, 2}, ins, 0, out);
  EXPECT_EQ(out.size(), 1u);
  out.clear();
  refine_triangle({0, 1, 2}, ins, 1u << kSouth, out);
  EXPECT_EQ(out, (std::vector<std::array<int, 3>>{{0, 3, 2}, {3, 1, 2}}));
  out.clear();
  refine_triangle({0, 1, 2}, ins, (1u << kSouth) | (1u << kWest), out);
  // West first: fan from 1 over 2 -> 4 -> 0; then south edge 0 -> 1 lies in (4, 0, 1).
  EXPECT_EQ(out, (std::vector<std::array<int, 3>>{{2, 4, 1}, {0, 3, 4}, {3, 1, 4}}));
}

TEST(TerrainlodPyramid, LevelsAndLattice) {
  const Pyramid& p = fbm_pyramid();
  ASSERT_EQ(p.levels, 3);
  EXPECT_EQ(p.tiles.size(), 1u + 4u + 16u + 64u);
  for (const auto& lv : p.level) EXPECT_EQ(1 << lv.lattice_bits, 16) << "T = B = 16 texels at level " << lv.level;
  // eps halves per level: one texel of 2^(L-l) cells of 4 m.
  EXPECT_DOUBLE_EQ(p.level[0].eps, 32.0);
  EXPECT_DOUBLE_EQ(p.level[2].eps, 8.0);
}

TEST(TerrainlodPyramid, EveryTransitionWithinEpsOfTheDem) { expect_within_eps(fbm_pyramid()); }

TEST(TerrainlodPyramid, SubTexelDetailRefinesTheLatticeAndKeepsTheBound) {
  // 1 m cells: eps_l is 2^(L-l) m, below what a texel lattice of this fBm can carry.
  const Pyramid p = make_pyramid(1.0);
  EXPECT_GT(p.level[0].lattice_bits, 4);
  for (int l = 1; l <= p.levels; ++l) EXPECT_GE(p.level[l].lattice_bits, p.level[l - 1].lattice_bits - 1);
  expect_within_eps(p);
}

TEST(TerrainlodPyramid, DecodingReproducesTheEncodersTriangles) {
  const Pyramid& p = fbm_pyramid();
  for (const auto& tile : p.tiles) {
    const std::string bytes = encode_tile(tile);
    const Tile d = decode_tile(bytes);
    EXPECT_EQ(d.id, tile.id);
    EXPECT_EQ(encode_tile(d), bytes) << "re-encoding is stable";
    for (unsigned m = 0; m < 16; ++m) {
      const auto g = p.geometry(tile.id.level);
      EXPECT_EQ(triangle_set(triangulate(d, m, g)), triangle_set(triangulate(tile, m, g)));
    }
  }
}

TEST(TerrainlodPyramid, SimplifiesInsideTheTiles) {
  const Pyramid& p = fbm_pyramid();
  const Tile* root = find(p, 0, 0, 0);
  ASSERT_NE(root, nullptr);
  EXPECT_LT(root->triangles.size(), 2u * 16 * 16) << "the root is coarser than its lattice";
  EXPECT_GE(root->triangles.size(), 62u) << "a polygon of the 64 border lattice points needs 62 triangles";
}

TEST(TerrainlodPyramid, NoCracksBetweenSameAndNextLevelNeighbours) {
  const Pyramid& p = fbm_pyramid();
  for (const auto& c : p.tiles) {
    const int l = c.id.level;
    const auto gc = p.geometry(l);
    const std::int64_t cells = gc.cells;
    // Same level, east neighbour, base triangulations.
    if (const Tile* e = find(p, l, c.id.x + 1, c.id.y)) {
      const std::int64_t x = (c.id.x + 1) * cells;
      EXPECT_EQ(border_edges(triangulate(c, 0, gc), true, x), border_edges(triangulate(*e, 0, gc), true, x));
    }
    // Next level across the north border: C refined towards N, the two children of C's
    // north neighbour unrefined on their south side.
    if (l + 1 <= p.levels && find(p, l, c.id.x, c.id.y + 1)) {
      const std::int64_t y = (c.id.y + 1) * cells;
      const auto gf = p.geometry(l + 1);
      const Tile* f0 = find(p, l + 1, 2 * c.id.x, 2 * c.id.y + 2);
      const Tile* f1 = find(p, l + 1, 2 * c.id.x + 1, 2 * c.id.y + 2);
      ASSERT_TRUE(f0 && f1);
      for (unsigned other : {0u, 1u << kWest, 1u << kEast}) {  // other sides don't matter
        auto fine = border_edges(triangulate(*f0, other, gf), false, y);
        const auto fine1 = border_edges(triangulate(*f1, other, gf), false, y);
        fine.insert(fine1.begin(), fine1.end());
        EXPECT_EQ(border_edges(triangulate(c, (1u << kNorth) | other, gc), false, y), fine)
            << "tile " << l << "/" << c.id.x << "/" << c.id.y;
      }
    }
  }
}

TEST(TerrainlodPyramid, BuildIsIndependentOfThreads) {
  HeightGrid g = fest::test::fbm_grid(6, 5, 40.0);
  BuildParams p;
  p.pyramid.tile = 8;
  p.threads = 1;
  const Pyramid a = build_pyramid(g, 1, 1, p);
  p.threads = 3;
  const Pyramid b = build_pyramid(g, 1, 1, p);
  ASSERT_EQ(a.tiles.size(), b.tiles.size());
  for (std::size_t t = 0; t < a.tiles.size(); ++t) EXPECT_EQ(encode_tile(a.tiles[t]), encode_tile(b.tiles[t]));
}

TEST(TerrainlodPyramid, TruncatedOrForeignTileIsBadInput) {
  const std::string bytes = encode_tile(fbm_pyramid().tiles[1]);
  EXPECT_THROW(decode_tile(bytes.substr(0, bytes.size() - 3)), fest::Error);
  EXPECT_THROW(decode_tile(bytes.substr(0, 20)), fest::Error);
  std::string bad = bytes;
  bad[0] = 'X';
  EXPECT_THROW(decode_tile(bad), fest::Error);
}

}  // namespace
