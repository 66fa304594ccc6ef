#pragma once
// Scan conversion of one projected triangle under the rasteriser's pixel-centre rule
// (rasterizer.hpp): pixel (x, y) is covered when none of the three edge functions at its
// centre has the sign opposite to the triangle's area (inclusive on edges, either
// orientation). Shared by the visibility buffer, the silhouette bytes and the silhouette
// runs of registration (docs/brdffit.md §6), so that all of them cover the same pixels.
//
// The covered pixels of a row are found as a span, not by testing every pixel of the
// bounding box: each computed edge function is monotone in x (x - p.x, a product by a
// constant and a difference from a constant are each monotone under rounding), so the
// pixels passing one edge's test form a half-line of the row and the covered pixels the
// intersection of three half-lines. Each end is estimated from the edge's crossing and
// then moved by the very test the per-pixel loop applies, so the span holds exactly the
// pixels that loop would accept.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "reflectance/camera.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::reflectance::scan {

constexpr double near_plane = 1e-9;

// Vertices in screen space: pixel x, y and camera depth z (z <= near: not drawable).
struct ScreenVertex {
  double x, y, z;
};

inline std::vector<ScreenVertex> project_vertices(const TriangleMesh& mesh, const PinholeCamera& cam) {
  std::vector<ScreenVertex> s(mesh.vertices.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Eigen::Vector3d xc = cam.to_camera(mesh.vertices[i]);
    if (xc.z() <= near_plane) {
      s[i] = {0, 0, xc.z()};
      continue;
    }
    const Eigen::Vector2d p = cam.project_camera(xc);
    s[i] = {p.x(), p.y(), xc.z()};
  }
  return s;
}

inline bool drawable(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  return a.z > near_plane && b.z > near_plane && c.z > near_plane;
}

// Edge function of the edge p -> q at the pixel centre (x, y), written once so that the
// span search and the per-pixel weights compute it identically.
inline double edge_function(const ScreenVertex& p, const ScreenVertex& q, int x, int y) {
  return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
}

// One edge p -> q of a triangle, set up once per triangle and once per row, testing
// pixels in the operations of edge_function (the same roundings, so the same answers).
class EdgeTest {
 public:
  enum Kind { constant, from_column, up_to_column };  // which pixels of a row pass

  EdgeTest(const ScreenVertex& p, const ScreenVertex& q, double sign)
      : px_(p.x), py_(p.y), dx_(q.x - p.x), k_(q.y - p.y), sign_(sign) {
    kind_ = k_ == 0 ? constant : (-sign * k_ > 0 ? from_column : up_to_column);
    inv_k_ = k_ == 0 ? 0.0 : 1.0 / k_;
  }
  Kind kind() const { return kind_; }
  void set_row(int y) { row_term_ = dx_ * (y - py_); }
  bool passes(int x) const { return !(sign_ * (row_term_ - k_ * (x - px_)) < 0); }
  // Where the edge crosses the row (an estimate: only `passes` decides).
  double crossing() const { return px_ + row_term_ * inv_k_; }

 private:
  double px_, py_, dx_, k_, sign_, inv_k_ = 0, row_term_ = 0;
  Kind kind_;
};

// Narrows [lo, hi] (columns of the edge's current row) to the pixels passing its test;
// lo > hi when none does. Each test is monotone along the row, so the walk from the
// estimated crossing ends at the exact first (last) passing column.
inline void clip_span_to_edge(const EdgeTest& e, int& lo, int& hi) {
  if (lo > hi) return;
  if (e.kind() == EdgeTest::constant) {  // the same at every column: all or nothing
    if (!e.passes(lo)) hi = lo - 1;
    return;
  }
  // The crossing clamped into [lo - 1, hi + 1] (NaN-safe) and truncated; the walks fix
  // the last unit.
  const double v = e.crossing();
  const int start = !(v > lo - 1) ? lo - 1 : (!(v < hi + 1) ? hi + 1 : static_cast<int>(v));
  if (e.kind() == EdgeTest::from_column) {  // find the first passing column
    int x = std::max(lo, start);
    while (x > lo && e.passes(x - 1)) --x;
    while (x <= hi && !e.passes(x)) ++x;
    lo = x;
  } else {  // find the last passing column
    int x = std::min(hi, start);
    while (x < hi && e.passes(x + 1)) ++x;
    while (x >= lo && !e.passes(x)) --x;
    hi = x;
  }
}

// Calls span(y, x0, x1) for every row y in [y0, y1) with covered pixels [x0, x1] (x1
// inclusive) of the triangle (a, b, c) in an image `width` pixels wide, rows ascending.
template <typename Span>
void scan_spans(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int width, int y0, int y1,
                Span&& span) {
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area == 0 || !std::isfinite(area)) return;
  const double xmin = std::min({a.x, b.x, c.x}), xmax = std::max({a.x, b.x, c.x});
  const double ymin = std::min({a.y, b.y, c.y}), ymax = std::max({a.y, b.y, c.y});
  const int px0 = std::max(0, static_cast<int>(std::ceil(xmin)));
  const int px1 = std::min(width - 1, static_cast<int>(std::floor(xmax)));
  const int py0 = std::max(y0, static_cast<int>(std::ceil(ymin)));
  const int py1 = std::min(y1 - 1, static_cast<int>(std::floor(ymax)));
  if (px0 > px1 || py0 > py1) return;
  const double sign = area > 0 ? 1.0 : -1.0;
  EdgeTest e0(b, c, sign), e1(c, a, sign), e2(a, b, sign);  // w0, w1, w2: opposite a, b, c
  for (int y = py0; y <= py1; ++y) {
    e0.set_row(y);
    e1.set_row(y);
    e2.set_row(y);
    int lo = px0, hi = px1;
    clip_span_to_edge(e0, lo, hi);
    clip_span_to_edge(e1, lo, hi);
    clip_span_to_edge(e2, lo, hi);
    if (lo <= hi) span(y, lo, hi);
  }
}

// Visits every pixel centre (x, y) with y in [y0, y1) inside the triangle with its
// normalised edge functions (w0, w1, w2) / area, the barycentrics of a, b, c.
template <typename Visit>
void scan_triangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, int width, int y0, int y1,
                   Visit&& visit) {
  double inv_area = 0;
  const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area != 0 && std::isfinite(area)) inv_area = 1.0 / area;
  scan_spans(a, b, c, width, y0, y1, [&](int y, int x0, int x1) {
    for (int x = x0; x <= x1; ++x) {
      const double w0 = edge_function(b, c, x, y);
      const double w1 = edge_function(c, a, x, y);
      const double w2 = edge_function(a, b, x, y);
      visit(x, y, w0 * inv_area, w1 * inv_area, w2 * inv_area);
    }
  });
}

}  // namespace fest::reflectance::scan
