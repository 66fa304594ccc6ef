#include "terrainlod/tin_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/error.hpp"

namespace fest::terrainlod {
namespace {

// Fills a bucket table (CSR) from the items' bucket ranges.
template <typename Range>
void fill_buckets(int buckets, int items, Range range, std::vector<int>& start, std::vector<int>& list) {
  start.assign(static_cast<std::size_t>(buckets) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (int b = 0; b < buckets; ++b) start[static_cast<std::size_t>(b) + 1] += start[static_cast<std::size_t>(b)];
      list.assign(static_cast<std::size_t>(start.back()), 0);
    }
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int i = 0; i < items; ++i)
      range(i, [&](int b) {
        if (pass == 0) ++start[static_cast<std::size_t>(b) + 1];
        else list[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = i;
      });
  }
}

}  // namespace

TinReference::TinReference(std::vector<GridPoint> vertices, std::vector<std::array<int, 3>> triangles, int x0, int y0,
                           int x1, int y1, int bucket)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)), x0_(x0), y0_(y0), bucket_(bucket) {
  if (bucket <= 0 || x1 <= x0 || y1 <= y0) throw runtime_failure("reference mesh: empty region or bucket size");
  nx_ = (x1 - x0 + bucket - 1) / bucket;
  ny_ = (y1 - y0 + bucket - 1) / bucket;
  for (const auto& t : triangles_)
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      edges_.push_back({std::min(a, b), std::max(a, b)});
    }
  std::sort(edges_.begin(), edges_.end());
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  const int buckets = nx_ * ny_;
  auto cover = [&](double lx, double ly, double hx, double hy, auto&& add) {
    int bx0, by0, bx1, by1;
    bucket_range(lx, ly, hx, hy, bx0, by0, bx1, by1);
    for (int by = by0; by <= by1; ++by)
      for (int bx = bx0; bx <= bx1; ++bx) add(by * nx_ + bx);
  };
  fill_buckets(buckets, static_cast<int>(vertices_.size()),
               [&](int i, auto&& add) { add(bucket_of(vertices_[static_cast<std::size_t>(i)].x, vertices_[static_cast<std::size_t>(i)].y)); },
               vertex_start_, vertex_items_);
  fill_buckets(buckets, static_cast<int>(triangles_.size()),
               [&](int i, auto&& add) {
                 const auto& t = triangles_[static_cast<std::size_t>(i)];
                 const GridPoint &a = vertices_[static_cast<std::size_t>(t[0])], &b = vertices_[static_cast<std::size_t>(t[1])],
                                 &c = vertices_[static_cast<std::size_t>(t[2])];
                 cover(std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::max({a.x, b.x, c.x}),
                       std::max({a.y, b.y, c.y}), add);
               },
               triangle_start_, triangle_items_);
  fill_buckets(buckets, static_cast<int>(edges_.size()),
               [&](int i, auto&& add) {
                 const GridPoint &p = vertices_[static_cast<std::size_t>(edges_[static_cast<std::size_t>(i)][0])],
                                 &q = vertices_[static_cast<std::size_t>(edges_[static_cast<std::size_t>(i)][1])];
                 cover(std::min(p.x, q.x), std::min(p.y, q.y), std::max(p.x, q.x), std::max(p.y, q.y), add);
               },
               edge_start_, edge_items_);
}

int TinReference::bucket_of(double x, double y) const {
  const int bx = std::clamp(static_cast<int>(std::floor((x - x0_) / bucket_)), 0, nx_ - 1);
  const int by = std::clamp(static_cast<int>(std::floor((y - y0_) / bucket_)), 0, ny_ - 1);
  return by * nx_ + bx;
}

void TinReference::bucket_range(double lo_x, double lo_y, double hi_x, double hi_y, int& bx0, int& by0, int& bx1,
                                int& by1) const {
  // A point on a bucket line belongs to both buckets: widen by one where it sits on one.
  bx0 = std::clamp(static_cast<int>(std::ceil((lo_x - x0_) / bucket_)) - 1, 0, nx_ - 1);
  by0 = std::clamp(static_cast<int>(std::ceil((lo_y - y0_) / bucket_)) - 1, 0, ny_ - 1);
  bx1 = std::clamp(static_cast<int>(std::floor((hi_x - x0_) / bucket_)), 0, nx_ - 1);
  by1 = std::clamp(static_cast<int>(std::floor((hi_y - y0_) / bucket_)), 0, ny_ - 1);
}

double TinReference::height_at(double x, double y) const {
  const GridPoint p{x, y, 0};
  const int b = bucket_of(x, y);
  for (int k = triangle_start_[static_cast<std::size_t>(b)]; k < triangle_start_[static_cast<std::size_t>(b) + 1]; ++k) {
    const auto& t = triangles_[static_cast<std::size_t>(triangle_items_[static_cast<std::size_t>(k)])];
    const GridPoint &a = vertices_[static_cast<std::size_t>(t[0])], &bb = vertices_[static_cast<std::size_t>(t[1])],
                    &c = vertices_[static_cast<std::size_t>(t[2])];
    const double wa = twice_area(p, bb, c), wb = twice_area(a, p, c), wc = twice_area(a, bb, p);
    if (wa < 0 || wb < 0 || wc < 0) continue;
    return (wa * a.z + wb * bb.z + wc * c.z) / (wa + wb + wc);
  }
  throw runtime_failure("reference mesh does not cover ({}, {})", x, y);
}

double TinReference::samples_error(const GridPoint& a, const GridPoint& b, const GridPoint& c,
                                   double stop_above) const {
  double worst = 0;
  for (const GridPoint* v : {&a, &b, &c}) {
    worst = std::max(worst, std::abs(v->z - height_at(v->x, v->y)));
    if (worst > stop_above) return worst;
  }
  const double d = twice_area(a, b, c);
  int bx0, by0, bx1, by1;
  bucket_range(std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}),
               bx0, by0, bx1, by1);
  for (int by = by0; by <= by1; ++by)
    for (int bx = bx0; bx <= bx1; ++bx) {
      const std::size_t bk = static_cast<std::size_t>(by * nx_ + bx);
      for (int k = vertex_start_[bk]; k < vertex_start_[bk + 1]; ++k) {
        const GridPoint& p = vertices_[static_cast<std::size_t>(vertex_items_[static_cast<std::size_t>(k)])];
        const double wa = twice_area(p, b, c), wb = twice_area(a, p, c), wc = twice_area(a, b, p);
        if (wa < 0 || wb < 0 || wc < 0) continue;
        worst = std::max(worst, std::abs((wa * a.z + wb * b.z + wc * c.z) / d - p.z));
        if (worst > stop_above) return worst;
      }
    }
  return worst;
}

double TinReference::edge_error(const GridPoint& p, const GridPoint& q, double stop_above) const {
  double worst = 0;
  int bx0, by0, bx1, by1;
  bucket_range(std::min(p.x, q.x), std::min(p.y, q.y), std::max(p.x, q.x), std::max(p.y, q.y), bx0, by0, bx1, by1);
  const double ex = q.x - p.x, ey = q.y - p.y;
  for (int by = by0; by <= by1; ++by)
    for (int bx = bx0; bx <= bx1; ++bx) {
      const std::size_t bk = static_cast<std::size_t>(by * nx_ + bx);
      for (int k = edge_start_[bk]; k < edge_start_[bk + 1]; ++k) {
        const auto& e = edges_[static_cast<std::size_t>(edge_items_[static_cast<std::size_t>(k)])];
        const GridPoint &r = vertices_[static_cast<std::size_t>(e[0])], &s = vertices_[static_cast<std::size_t>(e[1])];
        const double fx = s.x - r.x, fy = s.y - r.y;
        const double den = ex * fy - ey * fx;
        if (den == 0) continue;  // parallel: the end points are overlay vertices of their own
        const double tn = (r.x - p.x) * fy - (r.y - p.y) * fx, un = (r.x - p.x) * ey - (r.y - p.y) * ex;
        // Most edges of the buckets miss p -> q; the numerators tell without dividing:
        // rounding is monotone, so tn / den rounds to <= 0 when the signs differ (or tn is
        // 0) and to >= 1 when |tn| >= |den|, and a nonzero un / den keeps its sign.
        if (tn == 0 || (tn < 0) != (den < 0) || std::abs(tn) >= std::abs(den)) continue;
        if (un != 0 && (un < 0) != (den < 0)) continue;
        const double t = tn / den;  // along p -> q
        const double u = un / den;  // along r -> s
        if (t <= 0 || t >= 1 || u < 0 || u > 1) continue;
        worst = std::max(worst, std::abs(p.z + t * (q.z - p.z) - (r.z + u * (s.z - r.z))));
        if (worst > stop_above) return worst;
      }
    }
  return worst;
}

double TinReference::triangle_error(const GridPoint& a, const GridPoint& b, const GridPoint& c,
                                    double stop_above) const {
  double worst = samples_error(a, b, c, stop_above);
  for (const auto& [p, q] : {std::pair{&a, &b}, std::pair{&b, &c}, std::pair{&c, &a}}) {
    if (worst > stop_above) return worst;
    worst = std::max(worst, edge_error(*p, *q, stop_above));
  }
  return worst;
}

}  // namespace fest::terrainlod
