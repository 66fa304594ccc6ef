#include "terrainlod/dem_clip.hpp"

#include <utility>

namespace fest::terrainlod {
namespace {

// The point of segment pq where coordinate `axis` (0 = x, 1 = y) equals `at`; p and q on
// opposite sides. Computed from the lexicographically smaller end so the result does not
// depend on the order the edge is walked.
GridPoint cut(GridPoint p, GridPoint q, int axis, double at) {
  auto key = [](const GridPoint& g) { return std::array<double, 3>{g.x, g.y, g.z}; };
  if (key(q) < key(p)) std::swap(p, q);
  const double pa = axis == 0 ? p.x : p.y, qa = axis == 0 ? q.x : q.y;
  const double s = (at - pa) / (qa - pa);
  GridPoint r{p.x + s * (q.x - p.x), p.y + s * (q.y - p.y), p.z + s * (q.z - p.z)};
  (axis == 0 ? r.x : r.y) = at;  // exactly on the edge of the DEM
  return r;
}

// Sutherland-Hodgman against one half-plane coordinate <= at.
std::vector<GridPoint> clip_half(const std::vector<GridPoint>& poly, int axis, double at) {
  std::vector<GridPoint> out;
  const std::size_t n = poly.size();
  for (std::size_t k = 0; k < n; ++k) {
    const GridPoint& p = poly[k];
    const GridPoint& q = poly[(k + 1) % n];
    const bool p_in = (axis == 0 ? p.x : p.y) <= at, q_in = (axis == 0 ? q.x : q.y) <= at;
    if (p_in) out.push_back(p);
    if (p_in != q_in) out.push_back(cut(p, q, axis, at));
  }
  return out;
}

}  // namespace

std::vector<std::array<GridPoint, 3>> clip_to_dem(const std::array<TileTriangulation::Vertex, 3>& t, std::int64_t last_x,
                                                   std::int64_t last_y) {
  std::vector<std::array<GridPoint, 3>> out;
  std::vector<GridPoint> poly;
  bool inside = true;
  for (const auto& v : t) {
    poly.push_back({static_cast<double>(v.gx), static_cast<double>(v.gy), v.z});
    inside = inside && v.gx <= last_x && v.gy <= last_y;
  }
  if (inside) {
    out.push_back({poly[0], poly[1], poly[2]});
    return out;
  }
  poly = clip_half(poly, 0, static_cast<double>(last_x));
  if (poly.size() >= 3) poly = clip_half(poly, 1, static_cast<double>(last_y));
  if (poly.size() < 3) return out;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
    const std::array<GridPoint, 3> tri{poly[0], poly[k], poly[k + 1]};
    if (twice_area(tri[0], tri[1], tri[2]) == 0) continue;  // a sliver on the edge itself
    out.push_back(tri);
  }
  return out;
}

}  // namespace fest::terrainlod
