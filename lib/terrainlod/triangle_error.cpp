#include "terrainlod/triangle_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace fest::terrainlod {
namespace {

// Index of the cell holding coordinate x along an axis of n samples: floor(x) clamped to
// [0, n - 2]. Truncation is floor for x >= 0, and for -1 < x < 0 both clamp to 0: points on
// segments between grid points are never further outside (a rounding at most).
inline int cell_of(double x, int n) { return std::clamp(static_cast<int>(x), 0, n - 2); }

// The x of an edge P -> Q (integer end points, P.y < Q.y) on successive rows from P.y on,
// as exact floor and ceiling: one integer division per edge, none per row.
struct RowCrossing {
  int fl = 0, rem = 0;  // x(j) = fl + rem / den, 0 <= rem < den
  int step_q = 0, step_r = 0, den = 1;
  // Inlined: three calls per triangle, and the out-of-line copy GCC chose cost a call each
  // (1.5 % of a 10 m simplify's instructions).
#if defined(__GNUC__)
  [[gnu::always_inline]]
#endif
  void start(const GridPoint& p, const GridPoint& q) {
    den = static_cast<int>(q.y - p.y);
    const int dx = static_cast<int>(q.x - p.x);
    if (den == 1) {  // most edges of small triangles: no division
      step_q = dx, step_r = 0;
    } else {
      step_q = dx / den;
      step_r = dx % den;
      if (step_r < 0) step_r += den, --step_q;  // floor division
    }
    fl = static_cast<int>(p.x);
    rem = 0;
  }
  int floor() const { return fl; }
  int ceil() const { return fl + (rem != 0); }
  void next_row() {
    fl += step_q;
    rem += step_r;
    if (rem >= den) rem -= den, ++fl;
  }
};

// True when the diagonal crossings of lattice edge p -> q are exactly the samples the grid
// line crossings already visited, with the same t and the same interpolated value bit for
// bit, so they need no walk:
// - a vertical edge (x = i < W - 1): every crossing has x = p.x + t * 0 = i exactly, so
//   each family interpolates with weight 0, giving sample (i, y) itself, and the t of
//   x +- y = k is (y - p.y) / dy computed with the same two roundings;
// - a horizontal edge (y = j < H - 1) of length 2^m: there the diagonal families compute
//   x = p.x + t * dx, exact only when 1 / dx is (a power of two); then likewise.
// On the last row or column the grid line families weigh the sample by 1, which may round
// differently, so the diagonals are walked there as anywhere else.
inline bool diagonals_repeat(const GridPoint& p, const GridPoint& q, int nx, int ny) {
  auto integer = [](double v) { return std::abs(v) < double(1 << 30) && v == static_cast<double>(static_cast<int>(v)); };
  if (p.x == q.x) return p.x >= 0 && p.x < nx - 1 && integer(p.x) && integer(p.y) && integer(q.y);
  if (p.y != q.y || !(p.y >= 0 && p.y < ny - 1) || !integer(p.y)) return false;
  const double len = std::abs(q.x - p.x);
  if (!(len < double(1 << 30)) || !integer(p.x) || !integer(q.x)) return false;
  const int n = static_cast<int>(len);
  return (n & (n - 1)) == 0;
}

// max |gx * i + row - h[i]| over i in [i0, i1): the inner samples of one row. Two lanes of
// SSE2 where there is SSE2 (every x86-64): the same IEEE products, sums and differences
// per sample as the scalar loop (no fused multiply-add on this baseline), and the maximum
// of a set does not depend on the order it is taken in; heights are never NaN.
inline double row_max_error(double gx, double row, const double* h, int i0, int i1) {
  double worst = 0;
  int i = i0;
#if defined(__SSE2__)
  if (i1 - i0 >= 4) {
    const __m128d vgx = _mm_set1_pd(gx), vrow = _mm_set1_pd(row), sign = _mm_set1_pd(-0.0), two = _mm_set1_pd(2.0);
    __m128d vi = _mm_set_pd(i0 + 1.0, double(i0)), m = _mm_setzero_pd();
    for (; i + 2 <= i1; i += 2) {
      const __m128d e = _mm_sub_pd(_mm_add_pd(_mm_mul_pd(vgx, vi), vrow), _mm_loadu_pd(h + i));
      m = _mm_max_pd(m, _mm_andnot_pd(sign, e));
      vi = _mm_add_pd(vi, two);
    }
    worst = std::max(_mm_cvtsd_f64(m), _mm_cvtsd_f64(_mm_unpackhi_pd(m, m)));
  }
#endif
  for (; i < i1; ++i) worst = std::max(worst, std::abs(gx * i + row - h[i]));
  return worst;
}

// Integer coordinates under 2^24 (every engine triangle: its vertices are DEM samples):
// edge steps fit an int, and the edge functions' products (below 2^48) are exact doubles.
inline bool lattice_point(const GridPoint& p) {
  constexpr double kMax = 1 << 24;
  return std::abs(p.x) < kMax && std::abs(p.y) < kMax && p.x == static_cast<double>(static_cast<long long>(p.x)) &&
         p.y == static_cast<double>(static_cast<long long>(p.y));
}

// The samples part for any vertex coordinates: each row's span from the three edges,
// widened by a hair (the general form of the lattice path below).
double samples_error_any(const ReferenceSurface& ref, const GridPoint& a, const GridPoint& b, const GridPoint& c,
                         double stop_above) {
  const double d = twice_area(a, b, c);
  const int x0 = static_cast<int>(std::ceil(std::min({a.x, b.x, c.x})));
  const int x1 = static_cast<int>(std::floor(std::max({a.x, b.x, c.x})));
  const int y0 = static_cast<int>(std::ceil(std::min({a.y, b.y, c.y})));
  const int y1 = static_cast<int>(std::floor(std::max({a.y, b.y, c.y})));
  const double gx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / d;
  const double gy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / d;
  const double g0 = a.z - gx * a.x - gy * a.y;
  double worst = 0;
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

}  // namespace

// The reference on the overlay's breakpoints along an edge. Each family of lines meets the
// finest triangulation in a known place, so the reference there is a 1-D interpolation
// between two samples (no point location): on x = k the grid column, on y = k the grid
// row, on x + y = k and x - y = k the cell diagonal -- where the cell has that diagonal;
// elsewhere the reference is linear across the line and the point is no breakpoint.
// Crossing k of a family s(x, y) = k lies at t = (k - s(p)) / (s(q) - s(p)) along p -> q.
double edge_error(const ReferenceSurface& ref, const GridPoint& p, const GridPoint& q, double stop_above) {
  const HeightGrid& grid = ref.grid();
  const double* h = grid.h.data();
  const std::ptrdiff_t w = grid.width;
  const int nx = grid.width, ny = grid.height;
  const double dx = q.x - p.x, dy = q.y - p.y, dz = q.z - p.z;
  double worst = 0;
  // Visits k = the integers strictly between sp and sq; `at(k, t)` returns false once the
  // error exceeds stop_above.
  auto family = [&](double sp, double sq, auto&& at) {
    if (sp == sq) return true;
    const double lo = std::min(sp, sq), hi = std::max(sp, sq);
    double k = std::floor(lo) + 1;
    if (!(k < hi)) return true;  // no crossing (unit edges): no division
    const double inv = 1 / (sq - sp);
    for (; k < hi; k += 1)
      if (!at(k, (k - sp) * inv)) return false;
    return true;
  };
  auto visit = [&](double t, double r) {
    worst = std::max(worst, std::abs(p.z + t * dz - r));
    return worst <= stop_above;
  };
  const bool ok =
      family(p.x, q.x,
             [&](double k, double t) {  // grid column i = k
               const double y = p.y + t * dy;
               const int i = static_cast<int>(k), j = cell_of(y, ny);
               const double* c = h + j * w + i;
               return visit(t, c[0] + (y - j) * (c[w] - c[0]));
             }) &&
      family(p.y, q.y, [&](double k, double t) {  // grid row j = k
        const double x = p.x + t * dx;
        const int j = static_cast<int>(k), i = cell_of(x, nx);
        const double* c = h + j * w + i;
        return visit(t, c[0] + (x - i) * (c[1] - c[0]));
      });
  if (!ok || diagonals_repeat(p, q, nx, ny)) return worst;
  family(p.x + p.y, q.x + q.y,
         [&](double k, double t) {  // cell (i, j) with i + j + 1 = k holds the NW-SE diagonal
           const double x = p.x + t * dx;
           const int i = cell_of(x, nx), j = static_cast<int>(k) - 1 - i;
           if (j < 0 || j > ny - 2 || ref.ne_diagonal(i, j)) return true;
           const double* c = h + j * w + i;
           return visit(t, c[w] + (x - i) * (c[1] - c[w]));
         }) &&
      family(p.x - p.y, q.x - q.y, [&](double k, double t) {  // cell (i, j) with i - j = k holds SW-NE
        const double x = p.x + t * dx;
        const int i = cell_of(x, nx), j = i - static_cast<int>(k);
        if (j < 0 || j > ny - 2 || !ref.ne_diagonal(i, j)) return true;
        const double* c = h + j * w + i;
        return visit(t, c[0] + (x - i) * (c[w + 1] - c[0]));
      });
  return worst;
}

double triangle_samples_error(const ReferenceSurface& ref, const GridPoint& a, const GridPoint& b,
                              const GridPoint& c, double stop_above) {
  if (!lattice_point(a) || !lattice_point(b) || !lattice_point(c) || (a.y == b.y && b.y == c.y))
    return samples_error_any(ref, a, b, c, stop_above);
  const double d = twice_area(a, b, c);
  const int x0 = static_cast<int>(std::min({a.x, b.x, c.x})), x1 = static_cast<int>(std::max({a.x, b.x, c.x}));
  // The triangle's plane z = gx x + gy y + g0 for the samples strictly inside a row's span,
  // found at the first such row (small triangles have none: two divisions saved).
  double gx = 0, gy = 0, g0 = 0;
  bool plane = false;
  const HeightGrid& grid = ref.grid();
  double worst = 0;
  // The span's end samples can lie on an edge: interpolated by the edge functions, as the
  // general path does. twice_area(p, b, c) etc. are affine in p = (i, j); with integer
  // coordinates under 2^24 every term is an integer below 2^50, so this form gives the
  // very same doubles as twice_area, with no products per sample.
  const double ka = b.x * c.y - c.x * b.y, kai = b.y - c.y, kaj = c.x - b.x;
  const double kb = a.y * (c.x - a.x) - a.x * (c.y - a.y), kbi = c.y - a.y, kbj = a.x - c.x;
  const double kc = a.x * (b.y - a.y) - a.y * (b.x - a.x), kci = a.y - b.y, kcj = b.x - a.x;
  auto corner_check = [&](int i, double wa_row, double wb_row, double wc_row, const double* hr) {
    const double wa = wa_row + kai * i, wb = wb_row + kbi * i, wc = wc_row + kci * i;
    if (wa < 0 || wb < 0 || wc < 0) return;
    const double z = (wa * a.z + wb * b.z + wc * c.z) / d;
    worst = std::max(worst, std::abs(z - hr[i]));
  };
  // Rows from the lowest vertex to the highest: the span runs from the long edge (lowest to
  // highest) to the lower short edge below the middle vertex and the upper one from it on
  // (both give the middle vertex's x on its row, as does a horizontal edge's end there).
  const GridPoint *lo = &a, *mid = &b, *hi = &c;
  if (mid->y < lo->y) std::swap(lo, mid);
  if (hi->y < mid->y) std::swap(mid, hi);
  if (mid->y < lo->y) std::swap(lo, mid);
  const int y0 = static_cast<int>(lo->y), ym = static_cast<int>(mid->y), y1 = static_cast<int>(hi->y);
  RowCrossing long_edge, lower, upper;
  long_edge.start(*lo, *hi);
  if (y0 < ym) lower.start(*lo, *mid);
  if (ym < y1) upper.start(*mid, *hi);
  for (int j = y0; j <= y1; ++j) {
    int sf = static_cast<int>(mid->x), sc = sf;
    if (j < ym) {
      sf = lower.floor(), sc = lower.ceil();
      lower.next_row();
    } else if (ym < y1) {
      sf = upper.floor(), sc = upper.ceil();
      upper.next_row();
    }
    const int lf = long_edge.floor(), lc = long_edge.ceil();
    long_edge.next_row();
    const int i0 = std::max(x0, std::min(lc, sc)), i1 = std::min(x1, std::max(lf, sf));
    if (i0 > i1) continue;
    const double* hr = grid.h.data() + static_cast<std::ptrdiff_t>(j) * grid.width;
    const double wa_row = ka + kaj * j, wb_row = kb + kbj * j, wc_row = kc + kcj * j;
    corner_check(i0, wa_row, wb_row, wc_row, hr);
    if (i1 > i0) corner_check(i1, wa_row, wb_row, wc_row, hr);
    if (i1 - i0 >= 2) {
      if (!plane) {
        gx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / d;
        gy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / d;
        g0 = a.z - gx * a.x - gy * a.y;
        plane = true;
      }
      worst = std::max(worst, row_max_error(gx, gy * j + g0, hr, i0 + 1, i1));
    }
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
