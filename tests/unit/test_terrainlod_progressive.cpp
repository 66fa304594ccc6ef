// Progressive (parent-relative) tile coding (docs/terrainlod.md §4, our version; tile_parent
// and tile_codec): round trips for both codings, progressive and standalone decodes agree
// tile by tile on a built pyramid, and the bits of the inherited vertices follow from the
// geometry (docs/terrainlod.md §4 in our version: 1 present bit + k_parent - k_child height bits per
// inherited interior vertex, no xy bits; k_parent bits of G for a parent interior vertex
// on the child's border; nothing for the parent's border points).

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "expect_error.hpp"
#include "terrainlod/progressive_recode.hpp"
#include "terrainlod/pyramid_build.hpp"
#include "terrainlod/tile_codec.hpp"
#include "terrainlod/tile_parent.hpp"
#include "terrainlod_fixtures.hpp"

namespace {

using namespace fest::terrainlod;

// The tilted plane G = 7 gx + 3 gy + 50 in finest height units, gx, gy in child lattice
// steps from the parent's south-west corner.
std::int64_t plane_G(int gx, int gy) { return 7 * gx + 3 * gy + 50; }

bool on_border(int X, int Y, int n) { return X == 0 || Y == 0 || X == n || Y == n; }

// Every lattice point of an n x n tile, each cell split by its south-west to north-east
// diagonal (counter-clockwise triangles). `step` child steps per lattice step, (ox, oy)
// the tile's origin in child steps.
Tile lattice_tile(TileId id, int n, int k, int step, int ox, int oy) {
  Tile t;
  t.id = id;
  t.lattice_bits = 0;
  while ((1 << t.lattice_bits) < n) ++t.lattice_bits;
  t.k = k;
  for (int Y = 0; Y <= n; ++Y)
    for (int X = 0; X <= n; ++X) {
      const std::int64_t G = plane_G(ox + X * step, oy + Y * step);
      t.vertices.push_back({X, Y, on_border(X, Y, n) ? G : (G >> k)});
    }
  auto id_of = [n](int X, int Y) { return Y * (n + 1) + X; };
  for (int Y = 0; Y < n; ++Y)
    for (int X = 0; X < n; ++X) {
      t.triangles.push_back({id_of(X, Y), id_of(X + 1, Y), id_of(X + 1, Y + 1)});
      t.triangles.push_back({id_of(X, Y), id_of(X + 1, Y + 1), id_of(X, Y + 1)});
    }
  return t;
}

// The border lattice points and one interior vertex c, fanned from c.
Tile fan_tile(TileId id, int n, int k, int cx, int cy) {
  Tile t;
  t.id = id;
  t.lattice_bits = 0;
  while ((1 << t.lattice_bits) < n) ++t.lattice_bits;
  t.k = k;
  for (int b = 0; b < 4 * n; ++b) {
    const auto [X, Y] = border_point(b, n);
    t.vertices.push_back({X, Y, plane_G(X, Y)});
  }
  t.vertices.push_back({cx, cy, plane_G(cx, cy) >> k});
  for (int b = 0; b < 4 * n; ++b) t.triangles.push_back({4 * n, b, (b + 1) % (4 * n)});
  return t;
}

using Triangle = std::array<std::tuple<int, int, std::int64_t>, 3>;
std::set<Triangle> triangles_of(const Tile& t) {
  std::set<Triangle> out;
  for (const auto& tri : t.triangles) {
    Triangle q;
    for (int i = 0; i < 3; ++i) {
      const TileVertex& v = t.vertices[static_cast<std::size_t>(tri[static_cast<std::size_t>(i)])];
      q[static_cast<std::size_t>(i)] = {v.X, v.Y, v.code};
    }
    std::sort(q.begin(), q.end());
    out.insert(q);
  }
  return out;
}

// Parent: the root on a 4 x 4 lattice (2 child steps per step), k_p; child (1, 0, 0), the
// south-west quadrant, on a 4 x 4 lattice.
constexpr int kN = 4;

TEST(TerrainlodProgressive, InheritedVerticesCostPresentBitAndHeightBitsOnTiltedPlane) {
  for (const auto& [kp, kc] : {std::pair{2, 1}, std::pair{3, 1}, std::pair{3, 3}, std::pair{4, 0}}) {
    const Tile parent = lattice_tile({0, 0, 0}, kN, kp, 2, 0, 0);
    const Tile child = lattice_tile({1, 0, 0}, kN, kc, 1, 0, 0);
    TileSizes sizes;
    const std::string bytes = encode_tile_progressive(child, &parent, &sizes);
    ASSERT_EQ(sizes.coding, TileCoding::progressive);
    // Parent vertices in the child's square: (Xp, Yp) in [0, 2]^2. On the parent's border
    // (5): free. On the split lines Xp = 2 or Yp = 2 inside the parent (3): k_p bits of G.
    // Strictly inside (1, the child's (2, 2), kept): 1 present bit + k_p - k_c bits.
    EXPECT_EQ(sizes.inherited_bits, static_cast<std::size_t>(3 * kp + 1 + (kp - kc))) << kp << " " << kc;
    EXPECT_EQ(sizes.inherited_present, 1u);
    const Tile decoded = decode_tile(bytes, &parent);
    EXPECT_EQ(triangles_of(decoded), triangles_of(child));
    EXPECT_EQ(decoded.vertices.size(), child.vertices.size());
  }
}

TEST(TerrainlodProgressive, AbsentInheritedVertexCostsOnePresentBit) {
  const int kp = 3, kc = 1;
  const Tile parent = lattice_tile({0, 0, 0}, kN, kp, 2, 0, 0);
  // The child keeps only (1, 1) inside: the parent's (1, 1) (the child's (2, 2)) is gone.
  const Tile child = fan_tile({1, 0, 0}, kN, kc, 1, 1);
  TileSizes sizes;
  const std::string bytes = encode_tile_progressive(child, &parent, &sizes);
  ASSERT_EQ(sizes.coding, TileCoding::progressive);
  EXPECT_EQ(sizes.inherited_bits, static_cast<std::size_t>(3 * kp + 1));
  EXPECT_EQ(sizes.inherited_present, 0u);
  EXPECT_EQ(triangles_of(decode_tile(bytes, &parent)), triangles_of(child));
}

TEST(TerrainlodProgressive, ParentVerticesLandOnTheChildLatticeExactly) {
  const Tile parent = lattice_tile({0, 0, 0}, kN, 2, 2, 0, 0);
  // North-east quadrant on a lattice twice as fine (8 cells: 4 child steps per parent step).
  const ParentView v = parent_view(parent, {1, 1, 1}, 3);
  EXPECT_EQ(v.n, 8);
  EXPECT_EQ(v.ratio, 4);
  ASSERT_EQ(v.inherited.size(), 9u);  // parent (2..4, 2..4)
  for (const auto& iv : v.inherited) {
    EXPECT_EQ(iv.X % 4, 0);
    EXPECT_EQ(iv.Y % 4, 0);
  }
  // Parent order: rows from the south, then columns.
  EXPECT_EQ(std::make_pair(v.inherited.front().X, v.inherited.front().Y), std::make_pair(0, 0));
  EXPECT_EQ(std::make_pair(v.inherited.back().X, v.inherited.back().Y), std::make_pair(8, 8));
  // The parent's surface on the plane: exact where the plane's G is (parent border
  // heights are G; the interior's are bucket middles, so allow half a bucket there).
  // (The parent's lattice point (Xp, Yp) is plane_G(2 Xp, 2 Yp); the child's (X, Y) in this
  // quadrant is the parent's ((X + 8) / 4, (Y + 8) / 4).)
  EXPECT_EQ(v.surface_at(8, 0), 2 * plane_G(8, 4));   // the parent's east border point (4, 2)
  EXPECT_EQ(v.surface_at(8, 2), 2 * plane_G(8, 5));   // halfway between (4, 2) and (4, 3)
  EXPECT_THROW(parent_view(parent, {1, 2, 0}, 2), fest::Error);  // not its child
}

TEST(TerrainlodProgressive, FlatPlaneSendsNoInheritedBits) {
  HeightGrid g = fest::test::plane_grid(65, 65, 0, 0, 120);
  BuildParams p;
  p.pyramid.tile = 16;
  const Pyramid pyr = build_pyramid(g, 10, 10, p);
  for (const auto& tile : pyr.tiles) {
    // A flat tile keeps only its border lattice: a polygon of 4n points, 4n - 2 triangles.
    EXPECT_EQ(tile.vertices.size(), 4u * static_cast<unsigned>(tile.n()));
    EXPECT_EQ(tile.triangles.size(), 4u * static_cast<unsigned>(tile.n()) - 2u);
    if (tile.id.level == 0) continue;
    const Tile& parent = *std::find_if(pyr.tiles.begin(), pyr.tiles.end(), [&](const Tile& t) {
      return t.id == TileId{tile.id.level - 1, tile.id.x / 2, tile.id.y / 2};
    });
    TileSizes sizes;
    const std::string bytes = encode_tile_progressive(tile, &parent, &sizes);
    EXPECT_EQ(sizes.coding, TileCoding::progressive);
    EXPECT_EQ(sizes.inherited_bits, 0u) << "a flat parent has no interior vertices";
    EXPECT_EQ(triangles_of(decode_tile(bytes, &parent)), triangles_of(tile));
  }
}

// Decodes a pyramid's tiles (transmission order, root first) from their progressive
// coding, each with its decoded parent, and compares with the standalone decode.
void expect_codings_agree(const Pyramid& pyr) {
  std::map<std::tuple<int, int, int>, Tile> decoded;
  std::size_t progressive = 0;
  for (const auto& tile : pyr.tiles) {
    const std::string alone = encode_tile(tile);
    const TileId up{tile.id.level - 1, tile.id.x / 2, tile.id.y / 2};
    const Tile* parent = tile.id.level > 0 ? &decoded.at({up.level, up.x, up.y}) : nullptr;
    // As build writes it: the standalone stream recoded against the decoded parent.
    const std::string prog = recode_tile(alone, TileCoding::progressive, parent);
    if (tile.id.level > 0) {
      progressive += tile_coding(prog) == TileCoding::progressive;
      EXPECT_THROW(decode_tile(prog), fest::Error) << "a progressive tile needs its parent";
    }
    const Tile a = decode_tile(alone), b = decode_tile(prog, parent);
    EXPECT_EQ(b.id, tile.id);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t v = 0; v < a.vertices.size(); ++v) {
      EXPECT_EQ(a.vertices[v].X, b.vertices[v].X);
      EXPECT_EQ(a.vertices[v].Y, b.vertices[v].Y);
      EXPECT_EQ(a.vertices[v].code, b.vertices[v].code);
    }
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.fine_G, b.fine_G);
    EXPECT_EQ(triangles_of(a), triangles_of(tile));
    EXPECT_EQ(recode_tile(prog, tile_coding(prog), parent), prog) << "recoding is stable";
    if (tile.id == TileId{2, 1, 1}) {  // flipped body bytes: decoded or bad input, never a crash
      for (std::size_t at = kTileHeaderBytes; at < prog.size(); ++at) {
        std::string flipped = prog;
        flipped[at] = static_cast<char>(flipped[at] ^ 0x21);
        try {
          decode_tile(flipped, parent);
        } catch (const fest::Error& e) {
          EXPECT_EQ(e.status(), fest::Status::bad_input) << at;
        }
      }
    }
    decoded.emplace(std::make_tuple(tile.id.level, tile.id.x, tile.id.y), b);
  }
  EXPECT_EQ(progressive + 1, pyr.tiles.size()) << "every tile but the root agrees with its parent";
}

TEST(TerrainlodProgressive, ProgressiveAndStandaloneDecodesAgreeOnFbm) {
  HeightGrid g = fest::test::fbm_grid(7, 3, 60.0);  // 129 x 129, B = 16: L = 3
  BuildParams p;
  p.pyramid.tile = 16;
  p.threads = 2;
  expect_codings_agree(build_pyramid(g, 4, 4, p));
  // Steeper terrain: lattices refined beyond the texels (several child steps per parent step).
  expect_codings_agree(build_pyramid(g, 1, 1, p));
}

// The residual bound of docs/terrainlod.md §4, our version: the parent's base triangulation is within
// (4/3) eps_p of the DEM (reference l+2, quantized heights included) and a child vertex's
// G is the DEM sample rounded (1/2), so the parent-surface prediction floor(P / 2^k) of a
// child interior vertex misses its H = floor(G / 2^k) by at most ((4/3) eps_p + 1/2) / 2^k
// + 1 (finest quantum 1 here).
TEST(TerrainlodProgressive, ParentSurfacePredictsChildHeightsWithinTheBound) {
  HeightGrid g = fest::test::fbm_grid(7, 3, 60.0);
  BuildParams p;
  p.pyramid.tile = 16;
  p.threads = 2;
  const Pyramid pyr = build_pyramid(g, 4, 4, p);
  std::size_t checked = 0;
  for (const auto& tile : pyr.tiles) {
    if (tile.id.level == 0) continue;
    const Tile& parent = *std::find_if(pyr.tiles.begin(), pyr.tiles.end(), [&](const Tile& t) {
      return t.id == TileId{tile.id.level - 1, tile.id.x / 2, tile.id.y / 2};
    });
    const ParentView v = parent_view(parent, tile.id, tile.lattice_bits);
    const double bound = ((4.0 / 3.0) * parent.eps + 0.5) / std::ldexp(1.0, tile.k) + 1;
    for (const auto& vx : tile.vertices) {
      if (tile.on_border(vx)) continue;
      const std::int64_t s2 = v.surface_at(vx.X, vx.Y);
      ASSERT_NE(s2, kUnknownHeight) << "the parent covers the child's square";
      const std::int64_t predicted = s2 >> (tile.k + 1);
      EXPECT_LE(std::abs(static_cast<double>(vx.code - predicted)), bound) << tile.id.level << "/" << tile.id.x << "/" << tile.id.y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100u);
}

TEST(TerrainlodProgressive, RecodingALevelDoesNotDependOnThreads) {
  HeightGrid g = fest::test::fbm_grid(6, 5, 40.0);
  BuildParams p;
  p.pyramid.tile = 8;
  const Pyramid pyr = build_pyramid(g, 1, 1, p);
  std::vector<std::string> bytes;
  for (const auto& t : pyr.tiles) bytes.push_back(encode_tile(t));
  std::vector<CodedTile> parents, children;
  for (std::size_t i = 0; i < pyr.tiles.size(); ++i) {
    if (pyr.tiles[i].id.level == 1) parents.push_back({pyr.tiles[i].id, bytes[i]});
    if (pyr.tiles[i].id.level == 2) children.push_back({pyr.tiles[i].id, bytes[i]});
  }
  ASSERT_FALSE(children.empty());
  const auto one = recode_progressive(children, parents, 1), three = recode_progressive(children, parents, 3);
  EXPECT_EQ(one, three);
  // A child whose parent is not among those given is refused.
  EXPECT_THROW(recode_progressive(children, {}, 1), fest::Error);
}

TEST(TerrainlodProgressive, TruncatedProgressiveTileAndWrongParentAreBadInput) {
  const Tile parent = lattice_tile({0, 0, 0}, kN, 3, 2, 0, 0);
  const Tile child = lattice_tile({1, 0, 0}, kN, 1, 1, 0, 0);
  const std::string bytes = encode_tile_progressive(child, &parent);
  auto status_of = [](auto&& f) {
    try {
      f();
    } catch (const fest::Error& e) {
      return e.status();
    }
    return fest::Status::ok;
  };
  EXPECT_EQ(status_of([&] { decode_tile(bytes.substr(0, bytes.size() - 1), &parent); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([&] { decode_tile(bytes.substr(0, 40), &parent); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([&] { decode_tile(bytes); }), fest::Status::bad_input);
  const Tile other = lattice_tile({0, 1, 0}, kN, 3, 2, 0, 0);
  EXPECT_EQ(status_of([&] { decode_tile(bytes, &other); }), fest::Status::bad_input);
  // A cut anywhere in the body is caught (never a crash, never a silent short tile).
  for (std::size_t cut = kTileHeaderBytes; cut < bytes.size(); ++cut)
    EXPECT_THROW(decode_tile(bytes.substr(0, cut), &parent), fest::Error) << cut;
  // A flipped body byte decodes to something or is bad input, never a crash.
  for (std::size_t at = kTileHeaderBytes; at < bytes.size(); ++at) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x5a);
    try {
      decode_tile(flipped, &parent);
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::bad_input) << at;
    }
  }
}

TEST(TerrainlodProgressive, Version1StandaloneTilesStillDecode) {
  const Tile tile = lattice_tile({0, 0, 0}, kN, 2, 2, 0, 0);
  const std::string v2 = encode_tile(tile);
  ASSERT_EQ(v2.size() > kTileHeaderBytes, true);
  // Version 1: the same header without the coding byte at offset 62.
  std::string v1 = v2.substr(0, 62) + v2.substr(63);
  v1[4] = 1;
  EXPECT_EQ(tile_coding(v1), TileCoding::standalone);
  EXPECT_EQ(triangles_of(decode_tile(v1)), triangles_of(tile));
}

}  // namespace

// The format's limits (tile.hpp): a header naming a finer lattice, a larger quantum
// exponent or a corner height beyond them is refused before anything is allocated, and
// the encoder never writes what the decoder would refuse.
TEST(TileCodecLimits, HeaderBeyondTheFormatIsRefused) {
  const Tile t = lattice_tile({0, 0, 0}, 4, 0, 1, 0, 0);
  const std::string good = encode_tile(t);
  ASSERT_NO_THROW(decode_tile(good));
  auto patched = [&](std::size_t offset, std::uint8_t value) {
    std::string b = good;
    b[offset] = static_cast<char>(value);
    return b;
  };
  // Header bytes (tile_codec.cpp): 14 lattice bits, 15 fine bits, 16 k, 26..33 g0.
  fest::test::expect_bad_input([&] { decode_tile(patched(14, kMaxLatticeBits + 1)); }, "beyond the format's 2^13");
  fest::test::expect_bad_input([&] { decode_tile(patched(15, 16)); }, "beyond the format's 2^13");
  fest::test::expect_bad_input([&] { decode_tile(patched(16, kMaxHeightBits + 1)); }, "header out of range");
  fest::test::expect_bad_input([&] { decode_tile(patched(33, 0x40)); }, "beyond the format's range");  // g0 ~ 2^62

  Tile high = t;
  high.vertices[0].code = kMaxHeightCode + 1;
  EXPECT_THROW(encode_tile(high), fest::Error);
  Tile fine = t;
  fine.lattice_bits = kMaxLatticeBits + 1;
  EXPECT_THROW(encode_tile(fine), fest::Error);
}

// Heights at the very edge of the range survive the round trip (the limit is inclusive).
TEST(TileCodecLimits, HeightsAtTheLimitRoundTrip) {
  Tile t = lattice_tile({0, 0, 0}, 4, 3, 1, 0, 0);
  for (TileVertex& v : t.vertices) {
    const bool border = v.X == 0 || v.Y == 0 || v.X == 4 || v.Y == 4;
    const std::int64_t limit = border ? kMaxHeightCode : kMaxHeightCode >> t.k;
    v.code = (v.X + v.Y) % 2 ? limit : -limit;
  }
  const Tile back = decode_tile(encode_tile(t));
  ASSERT_EQ(back.vertices.size(), t.vertices.size());
  std::multiset<std::tuple<int, int, std::int64_t>> a, b;
  for (const auto& v : t.vertices) a.insert({v.X, v.Y, v.code});
  for (const auto& v : back.vertices) b.insert({v.X, v.Y, v.code});
  EXPECT_EQ(a, b);
}
