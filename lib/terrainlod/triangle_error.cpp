#include "terrainlod/triangle_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fest::terrainlod {
namespace {

// Crossings of segment p -> q with the lines s(x, y) = k for integers k strictly between
// s(p) and s(q); s is one of x, y, x + y, x - y.
template <typename S>
double edge_family_error(const ReferenceSurface& ref, const GridPoint& p, const GridPoint& q, S s, double stop_above) {
  const double sp = s(p.x, p.y), sq = s(q.x, q.y);
  if (sp == sq) return 0;
  const double lo = std::min(sp, sq), hi = std::max(sp, sq);
  double worst = 0;
  for (double k = std::floor(lo) + 1; k < hi; k += 1) {
    const double t = (k - sp) / (sq - sp);
    const double x = p.x + t * (q.x - p.x), y = p.y + t * (q.y - p.y);
    const double z = p.z + t * (q.z - p.z);
    worst = std::max(worst, std::abs(z - ref.height_at(x, y)));
    if (worst > stop_above) return worst;
  }
  return worst;
}

double edge_error(const ReferenceSurface& ref, const GridPoint& p, const GridPoint& q, double stop_above) {
  double e = edge_family_error(ref, p, q, [](double x, double) { return x; }, stop_above);
  if (e > stop_above) return e;
  e = std::max(e, edge_family_error(ref, p, q, [](double, double y) { return y; }, stop_above));
  if (e > stop_above) return e;
  e = std::max(e, edge_family_error(ref, p, q, [](double x, double y) { return x + y; }, stop_above));
  if (e > stop_above) return e;
  return std::max(e, edge_family_error(ref, p, q, [](double x, double y) { return x - y; }, stop_above));
}

}  // namespace

double triangle_error(const ReferenceSurface& ref, const GridPoint& a, const GridPoint& b, const GridPoint& c,
                      double stop_above) {
  const double d = twice_area(a, b, c);
  const int x0 = static_cast<int>(std::ceil(std::min({a.x, b.x, c.x})));
  const int x1 = static_cast<int>(std::floor(std::max({a.x, b.x, c.x})));
  const int y0 = static_cast<int>(std::ceil(std::min({a.y, b.y, c.y})));
  const int y1 = static_cast<int>(std::floor(std::max({a.y, b.y, c.y})));
  double worst = 0;
  // Samples inside or on the triangle, row by row over the span the edges cut from the
  // row (widened by a hair; the exact edge functions below decide). Edge functions of
  // integer points are exact in double, so "on an edge" is decided exactly.
  const GridPoint* v[3] = {&a, &b, &c};
  for (int j = y0; j <= y1; ++j) {
    double xl = x1 + 1.0, xr = x0 - 1.0;
    for (int e = 0; e < 3; ++e) {
      const GridPoint& p = *v[e];
      const GridPoint& q = *v[(e + 1) % 3];
      if (j < std::min(p.y, q.y) || j > std::max(p.y, q.y)) continue;
      if (p.y == q.y) {
        xl = std::min({xl, p.x, q.x});
        xr = std::max({xr, p.x, q.x});
      } else {
        const double x = p.x + (j - p.y) * (q.x - p.x) / (q.y - p.y);
        xl = std::min(xl, x);
        xr = std::max(xr, x);
      }
    }
    const int i0 = std::max(x0, static_cast<int>(std::ceil(xl - 1e-7)));
    const int i1 = std::min(x1, static_cast<int>(std::floor(xr + 1e-7)));
    for (int i = i0; i <= i1; ++i) {
      const GridPoint p{static_cast<double>(i), static_cast<double>(j), 0};
      const double wa = twice_area(p, b, c), wb = twice_area(a, p, c), wc = twice_area(a, b, p);
      if (wa < 0 || wb < 0 || wc < 0) continue;
      const double z = (wa * a.z + wb * b.z + wc * c.z) / d;
      worst = std::max(worst, std::abs(z - ref.sample(i, j)));
      if (worst > stop_above) return worst;
    }
  }
  for (const auto& [p, q] : {std::pair{&a, &b}, std::pair{&b, &c}, std::pair{&c, &a}}) {
    worst = std::max(worst, edge_error(ref, *p, *q, stop_above));
    if (worst > stop_above) return worst;
  }
  return worst;
}

}  // namespace fest::terrainlod
