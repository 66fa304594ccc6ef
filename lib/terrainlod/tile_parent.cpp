#include "terrainlod/tile_parent.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "terrainlod/transition.hpp"

namespace fest::terrainlod {
namespace {

// Weighted sums of heights need more than 64 bits in the worst case (areas up to 2^34 lattice
// units times heights); GCC and Clang's 128-bit integers keep them exact.
__extension__ typedef __int128 Int128;

// floor(a / b) for b > 0, exact on any machine (no floating point: the encoder and every
// decoder must predict the same integer).
std::int64_t floor_div(Int128 a, Int128 b) {
  Int128 q = a / b;
  if (a % b != 0 && a < 0) --q;
  return static_cast<std::int64_t>(q);
}

// Twice the parent vertex's height in finest units: 2 G on the border, the middle of the
// interior bucket (H 2^k + (2^k - 1) / 2, docs/terrainlod.md §4) doubled inside.
std::int64_t twice_height(const TileVertex& v, bool border, int k) {
  if (border) return 2 * v.code;
  return v.code * (std::int64_t{2} << k) + (std::int64_t{1} << k) - 1;
}

}  // namespace

int border_index(int X, int Y, int n) {
  if (Y == 0 && X < n) return X;
  if (X == n && Y < n) return n + Y;
  if (Y == n && X > 0) return 2 * n + (n - X);
  if (X == 0 && Y > 0) return 3 * n + (n - Y);
  return -1;
}

std::pair<int, int> border_point(int index, int n) {
  if (index < n) return {index, 0};
  if (index < 2 * n) return {n, index - n};
  if (index < 3 * n) return {n - (index - 2 * n), n};
  return {0, n - (index - 3 * n)};
}

ParentView parent_view(const Tile& parent, const TileId& child, int child_lattice_bits) {
  const std::string name = fmt::format("tile {}/{}/{}", child.level, child.x, child.y);
  if (!(parent.id == parent_id(child)))
    throw bad_input("{}: tile {}/{}/{} is not its parent", name, parent.id.level, parent.id.x, parent.id.y);
  const int np = parent.n();
  if (child_lattice_bits > kMaxLatticeBits || child_lattice_bits + 1 < parent.lattice_bits)
    throw bad_input("{}: its lattice does not refine its parent's", name);
  ParentView v;
  v.n = 1 << child_lattice_bits;
  v.ratio = 2 * v.n / np;
  v.parent_k = parent.k;
  const int n = v.n, r = v.ratio;
  const int qx = child.x & 1, qy = child.y & 1;
  const int ox = qx * n, oy = qy * n;  // the quadrant's origin in child steps from the parent's

  // Inherited vertices, in the parent's lattice order.
  for (const TileVertex& p : parent.vertices) {
    const int X = p.X * r - ox, Y = p.Y * r - oy;
    if (X < 0 || Y < 0 || X > n || Y > n) continue;
    InheritedVertex iv;
    iv.X = X, iv.Y = Y, iv.code = p.code;
    iv.parent_border = parent.on_border(p);
    iv.child_border = X == 0 || Y == 0 || X == n || Y == n;
    v.inherited.push_back(iv);
  }
  std::sort(v.inherited.begin(), v.inherited.end(),
            [](const InheritedVertex& a, const InheritedVertex& b) { return a.Y != b.Y ? a.Y < b.Y : a.X < b.X; });

  // Border heights the parent gives: its own border points, and its refinement points
  // (the finer level's border lattice, which is the child's) on its refinable sides.
  v.border_G.assign(static_cast<std::size_t>(4 * n), kUnknownHeight);
  for (const auto& iv : v.inherited)
    if (iv.parent_border) v.border_G[static_cast<std::size_t>(border_index(iv.X, iv.Y, n))] = iv.code;
  if (parent.fine_bits == child_lattice_bits && r > 1) {
    for (int s = kWest; s <= kNorth; ++s) {
      if (!(parent.refinable & (1u << s))) continue;
      // The child touches the parent's side s only from the quadrant on that side.
      if ((s == kWest && qx != 0) || (s == kEast && qx != 1) || (s == kSouth && qy != 0) || (s == kNorth && qy != 1)) continue;
      const bool vertical = s == kWest || s == kEast;
      const int per_step = r - 1;
      const auto& fine = parent.fine_G[static_cast<std::size_t>(s)];
      if (static_cast<std::size_t>(per_step) * np != fine.size()) continue;  // malformed: the child codes them itself
      for (std::size_t i = 0; i < fine.size(); ++i) {
        const int along = static_cast<int>(i) / per_step * r + static_cast<int>(i) % per_step + 1 - (vertical ? oy : ox);
        if (along < 0 || along > n) continue;
        const int X = vertical ? (s == kWest ? 0 : n) : along, Y = vertical ? along : (s == kSouth ? 0 : n);
        v.border_G[static_cast<std::size_t>(border_index(X, Y, n))] = fine[i];
      }
    }
  }

  // The parent's surface at every child lattice point: each parent triangle, in child
  // lattice units, fills the points of its closed area (a point on a shared edge gets the
  // same exact value from either triangle: the surface is linear along the edge).
  v.surface2.assign(static_cast<std::size_t>(n + 1) * (n + 1), kUnknownHeight);
  for (const auto& t : parent.triangles) {
    std::int64_t x[3], y[3], z[3];
    for (int i = 0; i < 3; ++i) {
      const TileVertex& p = parent.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])];
      x[i] = static_cast<std::int64_t>(p.X) * r - ox;
      y[i] = static_cast<std::int64_t>(p.Y) * r - oy;
      z[i] = twice_height(p, parent.on_border(p), parent.k);
    }
    const std::int64_t x0 = std::max<std::int64_t>(0, std::min({x[0], x[1], x[2]}));
    const std::int64_t x1 = std::min<std::int64_t>(n, std::max({x[0], x[1], x[2]}));
    const std::int64_t y0 = std::max<std::int64_t>(0, std::min({y[0], y[1], y[2]}));
    const std::int64_t y1 = std::min<std::int64_t>(n, std::max({y[0], y[1], y[2]}));
    if (x0 > x1 || y0 > y1) continue;
    const std::int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (area <= 0) continue;  // decoded triangles are counter-clockwise and not degenerate
    for (std::int64_t Y = y0; Y <= y1; ++Y)
      for (std::int64_t X = x0; X <= x1; ++X) {
        std::int64_t& out = v.surface2[static_cast<std::size_t>(Y * (n + 1) + X)];
        if (out != kUnknownHeight) continue;
        // Barycentric weights: twice the areas of the sub-triangles opposite each vertex.
        const std::int64_t w0 = (x[1] - X) * (y[2] - Y) - (x[2] - X) * (y[1] - Y);
        const std::int64_t w1 = (x[2] - X) * (y[0] - Y) - (x[0] - X) * (y[2] - Y);
        const std::int64_t w2 = (x[0] - X) * (y[1] - Y) - (x[1] - X) * (y[0] - Y);
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const Int128 num = static_cast<Int128>(w0) * z[0] + static_cast<Int128>(w1) * z[1] + static_cast<Int128>(w2) * z[2];
        out = floor_div(num, area);
      }
  }
  return v;
}

}  // namespace fest::terrainlod
