#include "terrainlod/tile.hpp"

#include <cmath>

#include "core/error.hpp"
#include "terrainlod/transition.hpp"

namespace fest::terrainlod {

double decode_height(std::int64_t code, bool border, int k, double delta_min) {
  if (border || k == 0) return delta_min * static_cast<double>(code);
  // The middle of the bucket of 2^k finest steps (docs/terrainlod.md §4).
  const double q = std::ldexp(1.0, k);
  return delta_min * (static_cast<double>(code) * q + (q - 1) / 2);
}

TileTriangulation triangulate(const Tile& tile, unsigned mask, const TileGeometry& geometry) {
  TileTriangulation out;
  const int n = tile.n();
  const std::int64_t step = geometry.cells / n;  // grid cells per lattice step
  const std::int64_t x0 = static_cast<std::int64_t>(tile.id.x) * geometry.cells;
  const std::int64_t y0 = static_cast<std::int64_t>(tile.id.y) * geometry.cells;
  for (const auto& v : tile.vertices)
    out.vertices.push_back({x0 + v.X * step, y0 + v.Y * step,
                            decode_height(v.code, tile.on_border(v), tile.k, geometry.delta_min)});
  mask &= tile.refinable;
  if (mask == 0) {
    out.triangles = tile.triangles;
    return out;
  }
  // Fine points per refined side, by position along the side, numbered after the tile's
  // vertices.
  const std::int64_t fine_step = geometry.cells / (2 << tile.fine_bits);
  if (fine_step <= 0 || step % fine_step != 0) throw bad_input("tile {}/{}/{}: finer lattice does not refine this one",
                                                               tile.id.level, tile.id.x, tile.id.y);
  const std::int64_t per_step = step / fine_step - 1;  // inserted points per coarse border edge
  std::array<std::int64_t, 4> first{};                 // id of the side's first fine point
  for (int s = kWest; s <= kNorth; ++s) {
    if (!(mask & (1u << s))) continue;
    if (static_cast<std::int64_t>(tile.fine_G[s].size()) != per_step * n)
      throw bad_input("tile {}/{}/{}: {} fine border points on side {}, expected {}", tile.id.level, tile.id.x,
                      tile.id.y, tile.fine_G[s].size(), s, per_step * n);
    first[s] = static_cast<std::int64_t>(out.vertices.size());
    for (std::size_t p = 0; p < tile.fine_G[s].size(); ++p) {
      const std::int64_t along = (static_cast<std::int64_t>(p) / per_step) * step + (static_cast<std::int64_t>(p) % per_step + 1) * fine_step;
      const bool vertical = s == kWest || s == kEast;
      const std::int64_t gx = vertical ? (s == kWest ? x0 : x0 + geometry.cells) : x0 + along;
      const std::int64_t gy = vertical ? y0 + along : (s == kSouth ? y0 : y0 + geometry.cells);
      out.vertices.push_back({gx, gy, geometry.delta_min * static_cast<double>(tile.fine_G[s][p])});
    }
  }
  for (const auto& t : tile.triangles) {
    std::array<EdgeInsert, 3> inserts;
    for (int e = 0; e < 3; ++e) {
      const TileVertex &p = tile.vertices[t[e]], &q = tile.vertices[t[(e + 1) % 3]];
      int side = -1;
      if (p.X == 0 && q.X == 0) side = kWest;
      else if (p.Y == 0 && q.Y == 0) side = kSouth;
      else if (p.X == n && q.X == n) side = kEast;
      else if (p.Y == n && q.Y == n) side = kNorth;
      if (side < 0 || !(mask & (1u << side))) continue;
      const bool vertical = side == kWest || side == kEast;
      const int a = vertical ? p.Y : p.X, b = vertical ? q.Y : q.X;
      if (std::abs(a - b) != 1)
        throw bad_input("tile {}/{}/{}: border edge longer than one lattice step", tile.id.level, tile.id.x, tile.id.y);
      inserts[e].side = side;
      const int lo = std::min(a, b);
      for (std::int64_t r = 0; r < per_step; ++r) {
        const std::int64_t idx = a < b ? r : per_step - 1 - r;  // ordered from p to q
        inserts[e].points.push_back(static_cast<int>(first[side] + lo * per_step + idx));
      }
    }
    refine_triangle(t, inserts, mask, out.triangles);
  }
  return out;
}

}  // namespace fest::terrainlod
