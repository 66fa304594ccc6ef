#include "terrainlod/transition.hpp"

namespace fest::terrainlod {

void refine_triangle(const std::array<int, 3>& t, const std::array<EdgeInsert, 3>& inserts, unsigned mask,
                     std::vector<std::array<int, 3>>& out) {
  // Work list of the triangle's current pieces; at most two refined edges per triangle in
  // a tile (three only in a tile of one cell, which --tile >= 4 excludes).
  std::vector<std::array<int, 3>> pieces{t};
  for (int side = kWest; side <= kNorth; ++side) {
    if (!(mask & (1u << side))) continue;
    for (int k = 0; k < 3; ++k) {
      const EdgeInsert& e = inserts[k];
      if (e.side != side || e.points.empty()) continue;
      const int u = t[k], w = t[(k + 1) % 3];
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        const auto q = pieces[p];
        int r = -1;
        for (int m = 0; m < 3; ++m)
          if (q[m] == u && q[(m + 1) % 3] == w) r = m;
        if (r < 0) continue;
        const int o = q[(r + 2) % 3];  // the vertex opposite the refined edge
        pieces.erase(pieces.begin() + static_cast<long>(p));
        int prev = u;
        for (int v : e.points) {
          pieces.push_back({prev, v, o});
          prev = v;
        }
        pieces.push_back({prev, w, o});
        break;
      }
    }
  }
  out.insert(out.end(), pieces.begin(), pieces.end());
}

}  // namespace fest::terrainlod
