#include "terrainlod/triangle_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fest::terrainlod {
namespace {

// The reference on the overlay's breakpoints along an edge. Each family of lines meets the
// finest triangulation in a known place, so the reference there is a 1-D interpolation
// between two samples (no point location): on x = k the grid column, on y = k the grid
// row, on x + y = k and x - y = k the cell diagonal -- where the cell has that diagonal;
// elsewhere the reference is linear across the line and the point is no breakpoint.
struct EdgeWalk {
  const ReferenceSurface& ref;
  const GridPoint& p;
  const GridPoint& q;
  double stop_above;
  double worst = 0;

  // Visits the crossings of p -> q with s(x, y) = k for integers k strictly between s(p)
  // and s(q); `reference(x, y, k)` returns the reference at the crossing or NaN when the
  // crossing is no breakpoint. Returns false once the error exceeds stop_above.
  template <typename S, typename R>
  bool family(S s, R reference) {
    const double sp = s(p.x, p.y), sq = s(q.x, q.y);
    if (sp == sq) return true;
    const double lo = std::min(sp, sq), hi = std::max(sp, sq), inv = 1 / (sq - sp);
    for (double k = std::floor(lo) + 1; k < hi; k += 1) {
      const double t = (k - sp) * inv;
      const double x = p.x + t * (q.x - p.x), y = p.y + t * (q.y - p.y);
      const double r = reference(x, y, k);
      if (std::isnan(r)) continue;
      worst = std::max(worst, std::abs(p.z + t * (q.z - p.z) - r));
      if (worst > stop_above) return false;
    }
    return true;
  }

  int cell_x(double x) const { return std::clamp(static_cast<int>(std::floor(x)), 0, ref.width() - 2); }
  int cell_y(double y) const { return std::clamp(static_cast<int>(std::floor(y)), 0, ref.height() - 2); }

  double run() {
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    const bool ok =
        family([](double x, double) { return x; },
               [&](double, double y, double k) {
                 const int i = static_cast<int>(k), j = cell_y(y);
                 const double h0 = ref.sample(i, j);
                 return h0 + (y - j) * (ref.sample(i, j + 1) - h0);
               }) &&
        family([](double, double y) { return y; },
               [&](double x, double, double k) {
                 const int j = static_cast<int>(k), i = cell_x(x);
                 const double h0 = ref.sample(i, j);
                 return h0 + (x - i) * (ref.sample(i + 1, j) - h0);
               }) &&
        family([](double x, double y) { return x + y; },
               [&](double x, double, double k) {
                 // Cell (i, j) with i + j + 1 = k holds the NW-SE diagonal x + y = k.
                 const int i = cell_x(x), j = static_cast<int>(k) - 1 - i;
                 if (j < 0 || j > ref.height() - 2 || ref.ne_diagonal(i, j)) return kNone;
                 const double h0 = ref.sample(i, j + 1);
                 return h0 + (x - i) * (ref.sample(i + 1, j) - h0);
               }) &&
        family([](double x, double y) { return x - y; },
               [&](double x, double, double k) {
                 // Cell (i, j) with i - j = k holds the SW-NE diagonal x - y = k.
                 const int i = cell_x(x), j = i - static_cast<int>(k);
                 if (j < 0 || j > ref.height() - 2 || !ref.ne_diagonal(i, j)) return kNone;
                 const double h0 = ref.sample(i, j);
                 return h0 + (x - i) * (ref.sample(i + 1, j + 1) - h0);
               });
    (void)ok;
    return worst;
  }
};

}  // namespace

double edge_error(const ReferenceSurface& ref, const GridPoint& p, const GridPoint& q, double stop_above) {
  return EdgeWalk{ref, p, q, stop_above}.run();
}

double triangle_samples_error(const ReferenceSurface& ref, const GridPoint& a, const GridPoint& b,
                              const GridPoint& c, double stop_above) {
  const double d = twice_area(a, b, c);
  const int x0 = static_cast<int>(std::ceil(std::min({a.x, b.x, c.x})));
  const int x1 = static_cast<int>(std::floor(std::max({a.x, b.x, c.x})));
  const int y0 = static_cast<int>(std::ceil(std::min({a.y, b.y, c.y})));
  const int y1 = static_cast<int>(std::floor(std::max({a.y, b.y, c.y})));
  // The triangle's plane z = gx x + gy y + g0 for the samples strictly inside a row's span.
  const double gx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / d;
  const double gy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / d;
  const double g0 = a.z - gx * a.x - gy * a.y;
  double worst = 0;
  // Samples inside or on the triangle, row by row over the span the edges cut from the
  // row (widened by a hair). Only the span's end samples can lie outside; they are decided
  // by the exact edge functions (exact in double for integer points).
  const GridPoint* v[3] = {&a, &b, &c};
  auto corner_check = [&](int i, int j) {
    const GridPoint p{static_cast<double>(i), static_cast<double>(j), 0};
    const double wa = twice_area(p, b, c), wb = twice_area(a, p, c), wc = twice_area(a, b, p);
    if (wa < 0 || wb < 0 || wc < 0) return;
    const double z = (wa * a.z + wb * b.z + wc * c.z) / d;
    worst = std::max(worst, std::abs(z - ref.sample(i, j)));
  };
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
    if (i0 > i1) continue;
    corner_check(i0, j);
    if (i1 > i0) corner_check(i1, j);
    const double row = gy * j + g0;
    for (int i = i0 + 1; i < i1; ++i) worst = std::max(worst, std::abs(gx * i + row - ref.sample(i, j)));
    if (worst > stop_above) return worst;
  }
  return worst;
}

double triangle_error(const ReferenceSurface& ref, const GridPoint& a, const GridPoint& b, const GridPoint& c,
                      double stop_above) {
  double worst = triangle_samples_error(ref, a, b, c, stop_above);
  if (worst > stop_above) return worst;
  for (const auto& [p, q] : {std::pair{&a, &b}, std::pair{&b, &c}, std::pair{&c, &a}}) {
    worst = std::max(worst, edge_error(ref, *p, *q, stop_above));
    if (worst > stop_above) return worst;
  }
  return worst;
}

}  // namespace fest::terrainlod
