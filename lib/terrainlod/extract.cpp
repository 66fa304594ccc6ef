#include "terrainlod/extract.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.hpp"

namespace fest::terrainlod {
namespace {

using Vec = std::array<double, 3>;
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
Vec normalized(const Vec& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

struct View {
  Vec eye, f, r, u;
  double tan_x, tan_y, near, far, f_px;
};

View make_view(const Camera& c) {
  View v;
  v.eye = c.eye;
  v.f = normalized(sub(c.target, c.eye));
  v.r = normalized(cross(v.f, c.up));
  v.u = cross(v.r, v.f);
  v.tan_y = std::tan(c.fovy_deg * M_PI / 360.0);
  v.tan_x = v.tan_y * c.width / c.height;
  v.near = c.near;
  v.far = c.far;
  v.f_px = (c.height / 2.0) / v.tan_y;
  return v;
}

struct Box {
  double x0, y0, z0, x1, y1, z1;
};

// Culled when all 8 corners are outside one of the six frustum planes.
bool outside(const View& v, const Box& b) {
  int out[6] = {0, 0, 0, 0, 0, 0};
  for (int k = 0; k < 8; ++k) {
    const Vec p{k & 1 ? b.x1 : b.x0, k & 2 ? b.y1 : b.y0, k & 4 ? b.z1 : b.z0};
    const Vec d = sub(p, v.eye);
    const double z = dot(d, v.f), x = dot(d, v.r), y = dot(d, v.u);
    out[0] += z < v.near;
    out[1] += z > v.far;
    out[2] += x > z * v.tan_x;
    out[3] += x < -z * v.tan_x;
    out[4] += y > z * v.tan_y;
    out[5] += y < -z * v.tan_y;
  }
  return std::any_of(out, out + 6, [](int n) { return n == 8; });
}

double distance_to(const Vec& p, const Box& b) {
  const double dx = std::max({b.x0 - p[0], 0.0, p[0] - b.x1});
  const double dy = std::max({b.y0 - p[1], 0.0, p[1] - b.y1});
  const double dz = std::max({b.z0 - p[2], 0.0, p[2] - b.z1});
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

TileId neighbour(const TileId& t, int side) {
  switch (side) {
    case kWest: return {t.level, t.x - 1, t.y};
    case kSouth: return {t.level, t.x, t.y - 1};
    case kEast: return {t.level, t.x + 1, t.y};
    default: return {t.level, t.x, t.y + 1};
  }
}

}  // namespace

void check_camera(const Camera& c) {
  for (const auto* v : {&c.eye, &c.target, &c.up})
    for (double x : *v)
      if (!std::isfinite(x)) throw bad_input("camera has a non-finite coordinate");
  const Vec f = sub(c.target, c.eye);
  if (dot(f, f) == 0) throw bad_input("camera has a zero-length view direction (eye = target)");
  if (dot(c.up, c.up) == 0) throw bad_input("camera has a zero-length up vector");
  const Vec s = cross(normalized(f), normalized(c.up));
  if (dot(s, s) < 1e-12) throw bad_input("camera looks along its up vector");
  if (!(c.fovy_deg > 0 && c.fovy_deg < 180)) throw bad_input("camera fovy_deg must be in (0, 180) (got {})", c.fovy_deg);
  if (c.width <= 0 || c.height <= 0) throw bad_input("camera image is {} x {} pixels; both must be positive", c.width, c.height);
  if (!(c.near > 0) || !(c.far > c.near)) throw bad_input("camera needs 0 < near < far (got {}, {})", c.near, c.far);
  if (!(c.tau_px > 0)) throw bad_input("tau_px must be positive (got {})", c.tau_px);
}

Selection select_tiles(const PyramidLayout& L, const Camera& camera,
                       const std::function<std::array<double, 2>(const TileId&)>& z_range) {
  check_camera(camera);
  const View view = make_view(camera);
  Selection sel;
  std::map<TileId, bool> leaves;  // drawn leaf -> closing-only
  std::set<TileId> inner;         // subdivided nodes
  auto box_of = [&](const TileId& t) {
    const auto z = z_range(t);
    const double c = L.cells[static_cast<std::size_t>(t.level)];
    return Box{L.origin_x + t.x * c * L.dx, L.origin_y + t.y * c * L.dy, z[0],
               L.origin_x + (t.x + 1) * c * L.dx, L.origin_y + (t.y + 1) * c * L.dy, z[1]};
  };
  // Seed 7.3 process(tile): cull, then keep or descend.
  std::vector<TileId> stack{{0, 0, 0}};
  while (!stack.empty()) {
    const TileId t = stack.back();
    stack.pop_back();
    if (!L.exists(t)) continue;
    ++sel.visited;
    const Box b = box_of(t);
    if (outside(view, b)) continue;
    const double texel = L.cells[static_cast<std::size_t>(t.level)] * std::max(L.dx, L.dy) / L.texels;
    const double d = std::max(distance_to(view.eye, b), view.near);
    if (t.level == L.levels || texel * view.f_px / d <= camera.tau_px) {
      leaves[t] = false;
      continue;
    }
    inner.insert(t);
    for (int k = 0; k < 4; ++k) stack.push_back({t.level + 1, 2 * t.x + (k & 1), 2 * t.y + (k >> 1)});
  }
  // Closing: a leaf whose neighbouring area is covered by a leaf two or more levels
  // coarser splits that leaf (its children are drawn with the parent's texture).
  std::map<TileId, TileId> texture_of;  // closing-only leaf -> the chosen ancestor
  std::vector<TileId> work;
  for (const auto& [t, c] : leaves) work.push_back(t);
  while (!work.empty()) {
    const TileId t = work.back();
    work.pop_back();
    if (!leaves.count(t)) continue;
    for (int side = kWest; side <= kNorth; ++side) {
      TileId a = neighbour(t, side);
      if (!L.exists(a)) continue;
      while (a.level > 0 && !leaves.count(a)) a = parent_id(a);
      if (!leaves.count(a) || a.level >= t.level - 1) continue;
      const TileId source = leaves[a] ? texture_of[a] : a;
      leaves.erase(a);
      inner.insert(a);
      for (int k = 0; k < 4; ++k) {
        const TileId ch{a.level + 1, 2 * a.x + (k & 1), 2 * a.y + (k >> 1)};
        if (!L.exists(ch)) continue;
        leaves[ch] = true;
        texture_of[ch] = source;
        work.push_back(ch);
      }
      work.push_back(t);
      break;
    }
  }
  for (const auto& [t, closing] : leaves) {
    SelectedTile s{t, 0, closing, closing ? texture_of.at(t) : t};
    for (int side = kWest; side <= kNorth; ++side)
      if (inner.count(neighbour(t, side))) s.mask |= 1u << side;
    sel.tiles.push_back(s);
  }
  return sel;
}

std::size_t count_open_edges(const PyramidLayout& L, const Selection& selection,
                             const std::vector<DrawnTriangle>& triangles) {
  using V = TileTriangulation::Vertex;
  std::map<std::pair<V, V>, std::pair<int, std::size_t>> uses;  // undirected edge -> (count, triangle)
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      V a = triangles[t].v[e], b = triangles[t].v[(e + 1) % 3];
      if (b < a) std::swap(a, b);
      auto& u = uses[{a, b}];
      ++u.first;
      u.second = t;
    }
  std::set<TileId> drawn;
  for (const auto& s : selection.tiles) drawn.insert(s.id);
  // The drawn tile covering grid point (x, y) (doubled coordinates: exact), if any.
  auto drawn_at = [&](std::int64_t x2, std::int64_t y2) {
    for (int l = 0; l <= L.levels; ++l) {
      const std::int64_t c2 = 2 * static_cast<std::int64_t>(L.cells[static_cast<std::size_t>(l)]);
      if (x2 < 0 || y2 < 0) return false;
      const TileId t{l, static_cast<int>(x2 / c2), static_cast<int>(y2 / c2)};
      if (drawn.count(t)) return true;
    }
    return false;
  };
  std::size_t open = 0;
  for (const auto& [e, u] : uses) {
    if (u.first == 2) continue;
    if (u.first > 2) {
      ++open;
      continue;
    }
    // A boundary edge is fine only if the area just beyond it (away from its triangle)
    // is not drawn. Edges of tiles are axis-parallel; probe half a cell outside.
    const auto& tri = triangles[u.second].v;
    const V& a = e.first;
    const V& b = e.second;
    if (a.gx != b.gx && a.gy != b.gy) {
      ++open;  // an inner diagonal used once: a hole inside a tile
      continue;
    }
    std::int64_t ox = 0, oy = 0;  // the triangle's third vertex tells the inside
    for (const auto& v : tri)
      if (!(v == a) && !(v == b)) ox = v.gx, oy = v.gy;
    const std::int64_t mx2 = a.gx + b.gx, my2 = a.gy + b.gy;
    std::int64_t px2 = mx2, py2 = my2;
    if (a.gx == b.gx) px2 += ox < a.gx ? 1 : -1;
    else py2 += oy < a.gy ? 1 : -1;
    if (drawn_at(px2, py2)) ++open;
  }
  return open;
}

HoleEdgeCount count_open_edges(const PyramidLayout& L, const Selection& selection, const std::vector<DrawnTriangle>& drawn,
                               const std::vector<DrawnTriangle>& holes) {
  using V = TileTriangulation::Vertex;
  HoleEdgeCount out;
  // The whole surface first: drawn and left-out triangles meet edge to edge.
  std::vector<DrawnTriangle> all(drawn);
  all.insert(all.end(), holes.begin(), holes.end());
  out.open = count_open_edges(L, selection, all);
  // Then each edge of a drawn triangle: drawn across (fine), or a hole's triangle across
  // (a hole edge), or nothing at all (then the whole-surface check above judged it).
  std::map<std::pair<V, V>, std::array<int, 2>> uses;  // edge -> (drawn, hole) triangles using it
  auto add = [&](const std::vector<DrawnTriangle>& tris, int k) {
    for (const auto& t : tris)
      for (int e = 0; e < 3; ++e) {
        V a = t.v[static_cast<std::size_t>(e)], b = t.v[static_cast<std::size_t>((e + 1) % 3)];
        if (b < a) std::swap(a, b);
        ++uses[{a, b}][static_cast<std::size_t>(k)];
      }
  };
  add(drawn, 0);
  add(holes, 1);
  for (const auto& [e, u] : uses)
    if (u[0] == 1 && u[1] == 1) ++out.hole_edges;
  return out;
}

}  // namespace fest::terrainlod
