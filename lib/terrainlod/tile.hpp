#pragma once
// One tile of the pyramid (docs/terrainlod.md §3-§4, our reconstruction): a free
// triangulation on the tile's lattice of n x n cells (n = 2^lattice_bits, one lattice step
// = one texel, or one DEM cell where texels are finer than cells), every border lattice
// point kept. Keeping the whole border lattice is our simplification of the seed's
// row-by-row border collapses: same-level neighbours then share their borders trivially,
// and a finer neighbour's border is the coarse border plus the midpoints, so the transition
// towards it is implied by the base triangulation (transition.hpp) and costs only the
// inserted points' heights.
//
// Heights: border points carry G, the height on the finest lattice (delta_min), so every
// tile meeting at a border point decodes the same value bit for bit whatever its level;
// interior vertices carry H = floor(G / 2^k) on the level's coarser lattice (docs/terrainlod.md §4).

#include <array>
#include <cstdint>
#include <vector>

namespace fest::terrainlod {

struct TileId {
  int level = 0, x = 0, y = 0;
  bool operator==(const TileId& o) const { return level == o.level && x == o.x && y == o.y; }
  bool operator<(const TileId& o) const {
    return level != o.level ? level < o.level : y != o.y ? y < o.y : x < o.x;
  }
};

// The tile one level up whose square contains t's (t.level > 0).
inline TileId parent_id(const TileId& t) { return {t.level - 1, t.x / 2, t.y / 2}; }

struct TileVertex {
  int X = 0, Y = 0;        // lattice coordinates, 0..n
  std::int64_t code = 0;   // G on the border, H = G >> k inside
};

// The format's limits (docs/terrainlod.md §4), checked by the builder before it codes and
// by the decoder before it allocates or adds: a tile lattice of at most 2^13 steps per side
// (the decoder holds the parent's surface on the child's lattice, (n + 1)^2 integers: 0.5 GB
// at the limit; a level that needs more is refused at build), and finest height codes G
// within +-2^52 (heights the double carried exactly), so every prediction (a sum of three
// codes) and every doubled or shifted code stays inside 64 bits.
constexpr int kMaxLatticeBits = 13;
constexpr int kMaxHeightBits = 52;
constexpr std::int64_t kMaxHeightCode = std::int64_t{1} << kMaxHeightBits;

struct Tile {
  TileId id;
  int lattice_bits = 0;    // n = 2^lattice_bits lattice cells per side
  int fine_bits = 0;       // lattice bits of the finer level's tiles (per their own side)
  int k = 0;               // interior height quantum exponent
  unsigned refinable = 0;  // bit per Side: a finer neighbour tile exists across that border
  std::vector<TileVertex> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from above
  // Per side (W, S, E, N): G of the finer neighbours' border points that are not on this
  // tile's lattice, by increasing x (S, N) or y (W, E). Empty unless refinable.
  std::array<std::vector<std::int64_t>, 4> fine_G;
  float eps = 0, err = 0, z_min = 0, z_max = 0;

  int n() const { return 1 << lattice_bits; }
  bool on_border(const TileVertex& v) const { return v.X == 0 || v.Y == 0 || v.X == n() || v.Y == n(); }
};

// How the decoded lattice maps to the DEM's grid and heights (from the pyramid manifest).
struct TileGeometry {
  int cells = 0;            // DEM cells per tile side at this tile's level
  double delta_min = 1;     // finest height quantum
};

// A tile's triangulation for one neighbour mask, in global DEM grid units.
struct TileTriangulation {
  struct Vertex {
    std::int64_t gx = 0, gy = 0;  // grid coordinates (integers: lattice steps are whole cells)
    double z = 0;
    bool operator==(const Vertex& o) const { return gx == o.gx && gy == o.gy && z == o.z; }
    bool operator<(const Vertex& o) const { return gx != o.gx ? gx < o.gx : gy != o.gy ? gy < o.gy : z < o.z; }
  };
  std::vector<Vertex> vertices;
  std::vector<std::array<int, 3>> triangles;
};

double decode_height(std::int64_t code, bool border, int k, double delta_min);

// The triangulation of `tile` for mask m (bit per Side: that neighbour is one level finer).
TileTriangulation triangulate(const Tile& tile, unsigned mask, const TileGeometry& geometry);

}  // namespace fest::terrainlod
