#include "brdffit/texture_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>
#include <unordered_set>
#include <utility>

#include "core/error.hpp"

namespace fest::brdffit {
namespace {

// Calls visit(x, y) for every texel whose centre lies strictly inside the triangle
// (centres exactly on an edge belong to neither side: that is what lets two triangles
// sharing an edge pass the overlap test).
template <class Visit>
void texel_centres_inside(const std::array<Eigen::Vector2d, 3>& c, Visit visit) {
  const double area = (c[1] - c[0]).x() * (c[2] - c[0]).y() - (c[1] - c[0]).y() * (c[2] - c[0]).x();
  if (!(std::abs(area) > 1e-12)) return;
  const double lo_x = std::min({c[0].x(), c[1].x(), c[2].x()}), hi_x = std::max({c[0].x(), c[1].x(), c[2].x()});
  const double lo_y = std::min({c[0].y(), c[1].y(), c[2].y()}), hi_y = std::max({c[0].y(), c[1].y(), c[2].y()});
  for (long y = static_cast<long>(std::floor(lo_y - 0.5)); y <= static_cast<long>(std::ceil(hi_y)); ++y)
    for (long x = static_cast<long>(std::floor(lo_x - 0.5)); x <= static_cast<long>(std::ceil(hi_x)); ++x) {
      const Eigen::Vector2d p(static_cast<double>(x) + 0.5, static_cast<double>(y) + 0.5);
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k) {
        const Eigen::Vector2d& a = c[static_cast<std::size_t>(k)];
        const Eigen::Vector2d& b = c[static_cast<std::size_t>((k + 1) % 3)];
        const double edge = (b - a).x() * (p - a).y() - (b - a).y() * (p - a).x();
        inside = edge * area > 1e-12 * std::abs(area);
      }
      if (inside) visit(x, y);
    }
}

std::uint64_t texel_key(long x, long y) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) | static_cast<std::uint32_t>(y);
}

// Triangles sharing each edge, for growing charts across edges.
std::vector<std::vector<std::uint32_t>> edge_neighbours(const reflectance::TriangleMesh& mesh) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = mesh.triangles[t][static_cast<std::size_t>(k)];
      std::uint32_t b = mesh.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
      if (a > b) std::swap(a, b);
      edges.emplace_back(static_cast<std::uint64_t>(a) << 32 | b, t);
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::vector<std::uint32_t>> out(mesh.triangles.size());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = i; b < j; ++b)
        if (a != b) out[edges[a].second].push_back(edges[b].second);
    i = j;
  }
  return out;
}

}  // namespace

FlatTriangles axis_projection(const reflectance::TriangleMesh& mesh, double texel_size) {
  if (!(texel_size > 0) || !std::isfinite(texel_size)) throw bad_input("texel size {} is not positive", texel_size);
  FlatTriangles flat;
  flat.group.resize(mesh.triangles.size());
  flat.corners.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d n = (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a);
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    const bool negative = n[axis] < 0;
    flat.group[t] = static_cast<std::uint32_t>(2 * axis + (negative ? 1 : 0));
    // The plane's two other axes, in an order that keeps the triangle counter-clockwise
    // seen from outside (mirroring would be harmless, but one orientation per group keeps
    // the tangent frames of a chart alike).
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (std::size_t k = 0; k < 3; ++k) {
      const Eigen::Vector3d& p = mesh.vertices[tri[k]];
      const double pu = p[u] / texel_size, pv = p[v] / texel_size;
      flat.corners[t][k] = negative ? Eigen::Vector2d(pv, pu) : Eigen::Vector2d(pu, pv);
    }
  }
  return flat;
}

double texel_size_for(const reflectance::TriangleMesh& mesh, int side, double fill) {
  if (side < 1 || !(fill > 0)) throw bad_input("atlas side {} and fill {} must be positive", side, fill);
  double projected = 0;
  for (const auto& tri : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[tri[0]];
    const Eigen::Vector3d n = (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a);
    projected += 0.5 * n.cwiseAbs().maxCoeff();  // the area in its axis plane
  }
  if (!(projected > 0) || !std::isfinite(projected)) throw bad_input("the mesh has no area to map to texels");
  return std::sqrt(projected / (fill * static_cast<double>(side) * static_cast<double>(side)));
}

double flat_texel_area(const FlatTriangles& flat) {
  double area = 0;
  for (const auto& c : flat.corners) {
    const Eigen::Vector2d e1 = c[1] - c[0], e2 = c[2] - c[0];
    area += 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  }
  return area;
}

TextureAtlas build_atlas(const reflectance::TriangleMesh& mesh, const FlatTriangles& flat, const AtlasOptions& options) {
  const std::size_t nt = mesh.triangles.size();
  if (flat.group.size() != nt || flat.corners.size() != nt)
    throw bad_input("the flat map has {} groups and {} corner triples for {} triangles", flat.group.size(),
                    flat.corners.size(), nt);
  if (options.gutter < 0) throw bad_input("gutter {} is negative", options.gutter);
  for (std::size_t t = 0; t < nt; ++t)
    for (const auto& c : flat.corners[t])
      if (!c.allFinite() || c.cwiseAbs().maxCoeff() > 1e9)
        throw bad_input("triangle {} has a texel coordinate that is not finite or beyond 1e9", t);

  TextureAtlas atlas;
  atlas.gutter = options.gutter;
  atlas.triangle_chart.assign(nt, 0);
  atlas.corners.resize(nt);

  // Grow charts breadth-first over shared edges within a group.
  const auto neighbours = edge_neighbours(mesh);
  std::vector<char> charted(nt, 0);
  std::vector<Eigen::Vector2d> chart_min;
  std::unordered_set<std::uint64_t> covered;
  std::vector<std::uint32_t> rejected;
  std::vector<std::uint32_t> pending;  // triangles a chart rejected: seeds before the next in order
  std::uint32_t next = 0;
  for (;;) {
    std::uint32_t seed = 0;
    if (!pending.empty()) {
      seed = pending.back();
      pending.pop_back();
    } else {
      while (next < nt && charted[next]) ++next;
      if (next == nt) break;
      seed = next;
    }
    if (charted[seed]) continue;
    AtlasChart chart;
    covered.clear();
    std::deque<std::uint32_t> queue{seed};
    charted[seed] = 1;
    while (!queue.empty()) {
      const std::uint32_t t = queue.front();
      queue.pop_front();
      bool overlaps = false;
      texel_centres_inside(flat.corners[t], [&](long x, long y) { overlaps = overlaps || covered.count(texel_key(x, y)); });
      if (overlaps) {
        charted[t] = 2;  // rejected by this chart; seeds a later one
        rejected.push_back(t);
        continue;
      }
      texel_centres_inside(flat.corners[t], [&](long x, long y) { covered.insert(texel_key(x, y)); });
      chart.triangles.push_back(t);
      for (std::uint32_t nb : neighbours[t])
        if (!charted[nb] && flat.group[nb] == flat.group[t]) {
          charted[nb] = 1;
          queue.push_back(nb);
        }
    }
    for (std::uint32_t t : rejected) {
      charted[t] = 0;
      pending.push_back(t);
    }
    rejected.clear();
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
    for (std::uint32_t t : chart.triangles)
      for (const auto& c : flat.corners[t]) {
        lo = lo.cwiseMin(c);
        hi = hi.cwiseMax(c);
      }
    const Eigen::Vector2d origin(std::floor(lo.x()) - options.gutter, std::floor(lo.y()) - options.gutter);
    chart.width = static_cast<int>(std::ceil(hi.x()) - origin.x()) + options.gutter;
    chart.height = static_cast<int>(std::ceil(hi.y()) - origin.y()) + options.gutter;
    chart.width = std::max(chart.width, 2 * options.gutter + 1);
    chart.height = std::max(chart.height, 2 * options.gutter + 1);
    for (std::uint32_t t : chart.triangles) atlas.triangle_chart[t] = static_cast<std::uint32_t>(atlas.charts.size());
    chart_min.push_back(origin);
    atlas.charts.push_back(std::move(chart));
  }

  // Shelf packing: tallest charts first, left to right, a new shelf when the row is full.
  double area = 0;
  int widest = 0;
  for (const AtlasChart& c : atlas.charts) {
    area += static_cast<double>(c.width) * c.height;
    widest = std::max(widest, c.width);
  }
  int width = options.max_width > 0 ? options.max_width : std::max(widest, static_cast<int>(std::ceil(std::sqrt(area))));
  if (widest > width) throw bad_input("a chart is {} texels wide, the atlas only {}", widest, width);
  std::vector<std::size_t> order(atlas.charts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const AtlasChart &ca = atlas.charts[a], &cb = atlas.charts[b];
    return ca.height != cb.height ? ca.height > cb.height : ca.width > cb.width;
  });
  int x = 0, y = 0, shelf = 0, used_width = 0;
  for (std::size_t i : order) {
    AtlasChart& c = atlas.charts[i];
    if (x + c.width > width) {
      y += shelf;
      x = 0;
      shelf = 0;
    }
    c.x = x;
    c.y = y;
    x += c.width;
    used_width = std::max(used_width, x);
    shelf = std::max(shelf, c.height);
  }
  atlas.width = options.max_width > 0 ? width : used_width;
  atlas.height = y + shelf;
  for (std::size_t t = 0; t < nt; ++t) {
    const std::size_t ci = atlas.triangle_chart[t];
    const Eigen::Vector2d shift = Eigen::Vector2d(atlas.charts[ci].x, atlas.charts[ci].y) - chart_min[ci];
    for (std::size_t k = 0; k < 3; ++k) atlas.corners[t][k] = flat.corners[t][k] + shift;
  }
  return atlas;
}

}  // namespace fest::brdffit
