// The pyramid against the guarantees of docs/terrainlod.md §1, §6: every tile and every
// one of its 16 transition triangulations within (4/3) eps_l of the DEM (eps_l with the
// DEM as the reference, 2 eps_l with level l+1) (re-measured here on
// the decoded tile, not taken from the builder), decoding reproduces the encoder's
// triangles exactly, and tiles meet without cracks or T-junctions: along every shared
// border the two sides have the same vertices and edges, bit for bit.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "terrainlod/extract.hpp"
#include "terrainlod/pyramid_build.hpp"
#include "terrainlod/quantized_mesh.hpp"
#include "terrainlod/tile_codec.hpp"
#include "terrainlod/transition.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using namespace fest::terrainlod;
using Vertex = TileTriangulation::Vertex;
using Edge = std::pair<Vertex, Vertex>;

Pyramid make_pyramid(double cell, Reference reference = Reference::level_plus_2, int tile = 16) {
  HeightGrid g = fest::test::fbm_grid(7, 3, 60.0);  // 129 x 129, B = 16: L = 3
  BuildParams p;
  p.pyramid.tile = tile;
  p.reference = reference;
  p.threads = 2;
  return build_pyramid(g, cell, cell, p);
}

// The bound against the DEM for each reference (docs/terrainlod.md §1): eps (1 + 1/4 + 1/16 + ...)
// for level l+2, eps (1 + 1/2 + 1/4 + ...) for level l+1.
double bound_factor(Reference r) {
  return r == Reference::original ? 1.0 : r == Reference::level_plus_1 ? 2.0 : 4.0 / 3.0;
}

// 4 m cells: one texel (2^(L-l) cells) holds the terrain's detail at every level.
const Pyramid& fbm_pyramid() {
  static const Pyramid pyr = make_pyramid(4.0);
  return pyr;
}

// Every tile decoded from its bytes, every mask, re-measured against the DEM.
void expect_within_eps(const Pyramid& p, double factor = 4.0 / 3.0) {
  HeightGrid g = fest::test::fbm_grid(7, 3, 60.0);
  const ReferenceSurface ref(g, DiagonalRule::shortest);
  for (const auto& tile : p.tiles) {
    const Tile d = decode_tile(encode_tile(tile));
    const auto& lv = p.level[static_cast<std::size_t>(tile.id.level)];
    for (unsigned m = 0; m < 16; ++m) {
      const double e = triangulation_error(ref, triangulate(d, m, p.geometry(tile.id.level)));
      // Leaves (eps 0) are the DEM up to integer heights: exact.
      EXPECT_LE(e, factor * lv.eps + 1e-9) << "tile " << tile.id.level << "/" << tile.id.x << "/" << tile.id.y << " mask " << m;
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

TEST(TerrainlodPyramid, EachReferenceKeepsItsBound) {
  // B = 8: L = 4, so with level l+2 (and level L = the DEM's surface) levels 1 and 0 are
  // measured against coarser meshes, with level l+1 levels 2..0.
  for (Reference r : {Reference::original, Reference::level_plus_1, Reference::level_plus_2}) {
    const Pyramid p = make_pyramid(2.0, r, 8);
    ASSERT_EQ(p.levels, 4);
    expect_within_eps(p, bound_factor(r));
  }
}

TEST(TerrainlodPyramid, LatticeStartKeepsTheBoundToo) {
  // The lattice start mesh (the fallback, and --start lattice) against the same check as
  // the default RTIN start; the decimated tiles are about the same size.
  HeightGrid g = fest::test::fbm_grid(7, 3, 60.0);
  BuildParams p;
  p.pyramid.tile = 16;
  p.threads = 2;
  p.start = StartRule::lattice;
  const Pyramid lattice = build_pyramid(g, 4.0, 4.0, p);
  expect_within_eps(lattice);
  std::size_t from_lattice = 0, from_rtin = 0;
  for (const auto& t : lattice.tiles) from_lattice += t.vertices.size();
  for (const auto& t : fbm_pyramid().tiles) from_rtin += t.vertices.size();
  EXPECT_LT(from_rtin, from_lattice + from_lattice / 10);
  EXPECT_LT(from_lattice, from_rtin + from_rtin / 10);
}

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

// Selection reads only headers: the figures must be the tile's own, and a header that
// is cut short or foreign must be refused like a whole tile.
TEST(TerrainlodPyramid, HeaderAloneGivesTheTilesFigures) {
  for (const auto& tile : fbm_pyramid().tiles) {
    const std::string bytes = encode_tile(tile);
    const TileHeader h = read_tile_header(std::string_view(bytes).substr(0, kTileHeaderBytes));
    EXPECT_EQ(h.id, tile.id);
    EXPECT_EQ(h.z_min, tile.z_min);
    EXPECT_EQ(h.z_max, tile.z_max);
    EXPECT_EQ(h.eps, tile.eps);
    EXPECT_EQ(h.err, tile.err);
    EXPECT_LE(h.z_min, h.z_max);
  }
  const std::string bytes = encode_tile(fbm_pyramid().tiles[1]);
  EXPECT_THROW(read_tile_header(std::string_view(bytes).substr(0, kTileHeaderBytes - 1)), fest::Error);
  std::string bad = bytes;
  bad[4] = 99;  // version
  EXPECT_THROW(read_tile_header(bad), fest::Error);
}

}  // namespace

namespace {

// An independent quantized-mesh-1.0 reader (layout from the format's description): the
// exported tile decodes to the base triangulation, up to the 15-bit quantization.
TEST(TerrainlodQuantizedMesh, DecodesToTheBaseTriangulation) {
  using namespace fest::terrainlod;
  const Pyramid& p = fbm_pyramid();
  const Tile& tile = p.tiles[3];  // a level-1 tile
  const TileGeometry g = p.geometry(tile.id.level);
  const TileTriangulation tri = triangulate(tile, 0, g);
  QmFrame f;
  f.gx0 = static_cast<std::int64_t>(tile.id.x) * g.cells;
  f.gy0 = static_cast<std::int64_t>(tile.id.y) * g.cells;
  f.cells = g.cells;
  const std::string b = encode_quantized_mesh(tri, f);
  std::size_t at = 0;
  auto rd = [&](auto& v) {
    std::memcpy(&v, b.data() + at, sizeof(v));
    at += sizeof(v);
  };
  at = 88;
  float zmin, zmax;
  std::memcpy(&zmin, b.data() + 24, 4);
  std::memcpy(&zmax, b.data() + 28, 4);
  std::uint32_t nv;
  rd(nv);
  ASSERT_EQ(nv, tri.vertices.size());
  std::vector<int> uvh[3];
  for (auto& a : uvh) {
    int prev = 0;
    for (std::uint32_t i = 0; i < nv; ++i) {
      std::uint16_t z;
      rd(z);
      prev += (z >> 1) ^ -(z & 1);
      a.push_back(prev);
    }
  }
  std::uint32_t nt;
  rd(nt);
  ASSERT_EQ(nt, tri.triangles.size());
  std::set<std::array<std::array<long, 3>, 3>> got, want;
  std::map<std::pair<long, long>, double> got_z, want_z;
  std::uint32_t highest = 0;
  auto key = [](std::array<std::array<long, 3>, 3> t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  const double hq = (zmax - zmin) / 32767.0;
  for (std::uint32_t t = 0; t < nt; ++t) {
    std::array<std::array<long, 3>, 3> tt;
    for (int k = 0; k < 3; ++k) {
      std::uint16_t c;
      rd(c);
      const std::uint32_t idx = highest - c;
      if (c == 0) ++highest;
      // Back to lattice steps of the tile and to heights within one height quantum.
      tt[k] = {std::lround(uvh[0][idx] * 16.0 / 32767.0), std::lround(uvh[1][idx] * 16.0 / 32767.0), 0};
      got_z[{tt[k][0], tt[k][1]}] = zmin + uvh[2][idx] * hq;
    }
    got.insert(key(tt));
  }
  const std::int64_t step = g.cells / 16;
  for (const auto& t : tri.triangles) {
    std::array<std::array<long, 3>, 3> tt;
    for (int k = 0; k < 3; ++k) {
      const auto& v = tri.vertices[t[k]];
      tt[k] = {static_cast<long>((v.gx - f.gx0) / step), static_cast<long>((v.gy - f.gy0) / step), 0};
      want_z[{tt[k][0], tt[k][1]}] = v.z;
    }
    want.insert(key(tt));
  }
  EXPECT_EQ(got, want);
  ASSERT_EQ(got_z.size(), want_z.size());
  for (const auto& [xy, z] : want_z) EXPECT_NEAR(got_z[xy], z, hq / 2 + 1e-4) << "height within half a 15-bit step";
}

}  // namespace

namespace {

using namespace fest::terrainlod;

TEST(TerrainlodSelect, LookingStraightDownFollowsTheDistanceRuleAndCloses) {
  const PyramidLayout L = fest::test::small_layout();
  Camera c;
  c.eye = {150, 420, 600};
  c.target = {150, 420, 0};
  c.up = {0, 1, 0};
  c.fovy_deg = 120;
  c.width = c.height = 512;
  c.tau_px = 3;
  const auto sel = select_tiles(L, c, [](const TileId&) { return std::array<double, 2>{0, 0}; });
  const double f_px = 256.0 / std::tan(M_PI / 3);  // (height / 2) / tan(fovy / 2)
  std::map<TileId, unsigned> drawn;
  for (const auto& s : sel.tiles) drawn[s.id] = s.mask;
  auto dist = [&](const TileId& t) {
    const double side = L.cells[t.level] * 10.0;
    const double x0 = t.x * side, y0 = t.y * side;
    const double dx = std::max({x0 - 150, 0.0, 150 - (x0 + side)}), dy = std::max({y0 - 420, 0.0, 420 - (y0 + side)});
    return std::sqrt(dx * dx + dy * dy + 600.0 * 600.0);
  };
  auto sufficient = [&](const TileId& t) { return t.level == L.levels || (L.cells[t.level] * 10.0 / 16) * f_px / dist(t) <= 3; };
  ASSERT_FALSE(sel.tiles.empty());
  std::set<int> levels;
  for (const auto& s : sel.tiles) levels.insert(s.id.level);
  EXPECT_GE(levels.size(), 2u) << "near tiles fine, far tiles coarse; got level " << *levels.begin() << " x " << sel.tiles.size();
  for (const auto& s : sel.tiles) {
    // Closed form: a tile chosen by the rule is sufficient and its parent was not.
    if (s.closing_only) continue;  // split to close the quadtree, not by the rule
    EXPECT_TRUE(sufficient(s.id)) << s.id.level << "/" << s.id.x << "/" << s.id.y;
    if (s.id.level > 0) {
      EXPECT_FALSE(sufficient({s.id.level - 1, s.id.x / 2, s.id.y / 2}));
    }
  }
  // The drawn tiles tile the visible ground without overlap: no drawn tile has a drawn
  // ancestor.
  for (const auto& [t, m] : drawn)
    for (TileId a{t.level - 1, t.x / 2, t.y / 2}; a.level >= 0; a = {a.level - 1, a.x / 2, a.y / 2})
      EXPECT_FALSE(drawn.count(a));
  // Restricted quadtree and masks: along every side, the drawn tiles touching it are
  // at most one level apart, and the mask bit is set exactly when they are finer.
  for (const auto& [t, m] : drawn) {
    const int side_cells = L.cells[t.level];
    for (int s = 0; s < 4; ++s) {
      int finer = 0, same_or_coarser = 0;
      for (const auto& [u, mu] : drawn) {
        if (u == t) continue;
        const int us = L.cells[u.level];
        // Do the squares share a piece of side s of t?
        const long tx0 = static_cast<long>(t.x) * side_cells, ty0 = static_cast<long>(t.y) * side_cells;
        const long ux0 = static_cast<long>(u.x) * us, uy0 = static_cast<long>(u.y) * us;
        const bool vertical = s == kWest || s == kEast;
        const long line = s == kWest ? tx0 : s == kEast ? tx0 + side_cells : s == kSouth ? ty0 : ty0 + side_cells;
        const long u_near = s == kWest ? ux0 + us : s == kEast ? ux0 : s == kSouth ? uy0 + us : uy0;
        if (u_near != line) continue;
        const long a0 = vertical ? ty0 : tx0, a1 = a0 + side_cells, b0 = vertical ? uy0 : ux0, b1 = b0 + us;
        if (std::min(a1, b1) <= std::max(a0, b0)) continue;
        EXPECT_LE(std::abs(u.level - t.level), 1) << "restricted quadtree";
        (u.level > t.level ? finer : same_or_coarser)++;
      }
      EXPECT_EQ((m >> s) & 1u, finer > 0 ? 1u : 0u) << "mask of " << t.level << "/" << t.x << "/" << t.y << " side " << s;
      if (finer) {
        EXPECT_EQ(same_or_coarser, 0);
      }
    }
  }
}

TEST(TerrainlodSelect, CullingKeepsOnlyTilesInFront) {
  const PyramidLayout L = fest::test::small_layout();
  Camera c;
  c.eye = {-100, 640, 50};
  c.target = {-200, 640, 0};  // looking west, away from the terrain
  c.width = 640, c.height = 480;
  const auto sel = select_tiles(L, c, [](const TileId&) { return std::array<double, 2>{0, 0}; });
  EXPECT_TRUE(sel.tiles.empty());
  c.up = {0, 0, 1};
  c.target = c.eye;
  EXPECT_THROW(check_camera(c), fest::Error);
  c.target = {-100, 640, 0};  // straight down with up = z
  EXPECT_THROW(check_camera(c), fest::Error);
}

}  // namespace
