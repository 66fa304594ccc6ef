#include "ffd/basis.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.hpp"

namespace fest::ffd {

const char* basis_name(Basis b) noexcept {
  switch (b) {
    case Basis::bernstein: return "bernstein";
    case Basis::bspline: return "bspline";
    case Basis::linear: return "linear";
    case Basis::catmull_rom: return "catmull-rom";
  }
  return "?";
}

Basis basis_from_name(const char* name) {
  if (std::strcmp(name, "bernstein") == 0) return Basis::bernstein;
  if (std::strcmp(name, "bspline") == 0) return Basis::bspline;
  if (std::strcmp(name, "linear") == 0) return Basis::linear;
  if (std::strcmp(name, "catmull-rom") == 0) return Basis::catmull_rom;
  throw usage_error("unknown basis '{}' (bernstein, bspline, linear, catmull-rom)", name);
}

namespace {

int degree_of(int count) { return std::min(3, count - 1); }

// Knot t_j of the clamped uniform knot vector (count + p + 1 knots): p + 1 zeros,
// count - p - 1 uniform interior knots, p + 1 ones.
double knot(int count, int p, int j) {
  if (j <= p) return 0.0;
  if (j >= count) return 1.0;
  return static_cast<double>(j - p) / (count - p);
}

// Bernstein polynomials of degree `n` at s into b[0..n].
void bernstein_values(int n, double s, double* b) {
  double ps[max_axis_points], pt[max_axis_points];
  ps[0] = pt[0] = 1;
  for (int i = 1; i <= n; ++i) {
    ps[i] = ps[i - 1] * s;
    pt[i] = pt[i - 1] * (1 - s);
  }
  double binom = 1;  // C(n, i)
  for (int i = 0; i <= n; ++i) {
    b[i] = binom * ps[i] * pt[n - i];
    binom = binom * (n - i) / (i + 1);
  }
}

void bernstein(int count, double s, AxisWeights& out, bool derivatives) {
  const int n = count - 1;
  bernstein_values(n, s, out.w.data());
  out.first = 0;
  out.count = count;
  if (!derivatives) return;
  // d/ds B_{i,n} = n (B_{i-1,n-1} - B_{i,n-1}).
  double lower[max_axis_points];
  bernstein_values(n - 1, s, lower);
  for (int i = 0; i <= n; ++i) {
    const double a = i >= 1 ? lower[i - 1] : 0.0, b = i <= n - 1 ? lower[i] : 0.0;
    out.dw[static_cast<std::size_t>(i)] = n * (a - b);
  }
}

// Cox-de Boor with first derivatives (The NURBS Book, algorithm A2.3 for k = 1).
void bspline(int count, double s, AxisWeights& out) {
  const int p = degree_of(count);
  // Span index: t_span <= s < t_span+1, with s = 1 in the last non-empty span.
  int span = p + static_cast<int>(std::floor(s * (count - p)));
  span = std::clamp(span, p, count - 1);
  double left[4], right[4], ndu[4][4];
  ndu[0][0] = 1;
  for (int j = 1; j <= p; ++j) {
    left[j] = s - knot(count, p, span + 1 - j);
    right[j] = knot(count, p, span + j) - s;
    double saved = 0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double tmp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * tmp;
      saved = left[j - r] * tmp;
    }
    ndu[j][j] = saved;
  }
  out.first = span - p;
  out.count = p + 1;
  for (int r = 0; r <= p; ++r) {
    out.w[static_cast<std::size_t>(r)] = ndu[r][p];
    double d = 0;
    if (p >= 1) {
      // N'_{i,p} = p [N_{i,p-1}/(t_{i+p}-t_i) - N_{i+1,p-1}/(t_{i+p+1}-t_{i+1})], with the
      // degree p-1 values in column p-1 of ndu and the knot differences in its lower part.
      if (r >= 1) d += ndu[r - 1][p - 1] / ndu[p][r - 1];
      if (r <= p - 1) d -= ndu[r][p - 1] / ndu[p][r];
      d *= p;
    }
    out.dw[static_cast<std::size_t>(r)] = d;
  }
}

void linear(int count, double s, AxisWeights& out) {
  const int cells = count - 1;
  int c = std::clamp(static_cast<int>(std::floor(s * cells)), 0, cells - 1);
  const double f = s * cells - c;
  out.first = c;
  out.count = 2;
  out.w[0] = 1 - f;
  out.w[1] = f;
  out.dw[0] = -cells;
  out.dw[1] = cells;
}

void catmull_rom(int count, double s, AxisWeights& out) {
  const int cells = count - 1;
  int c = std::clamp(static_cast<int>(std::floor(s * cells)), 0, cells - 1);
  const double f = s * cells - c, f2 = f * f, f3 = f2 * f;
  // Uniform Catmull-Rom weights of P_{c-1}, P_c, P_{c+1}, P_{c+2} and their derivatives.
  double w[4] = {0.5 * (-f3 + 2 * f2 - f), 0.5 * (3 * f3 - 5 * f2 + 2), 0.5 * (-3 * f3 + 4 * f2 + f), 0.5 * (f3 - f2)};
  double d[4] = {0.5 * (-3 * f2 + 4 * f - 1), 0.5 * (9 * f2 - 10 * f), 0.5 * (-9 * f2 + 8 * f + 1), 0.5 * (3 * f2 - 2 * f)};
  for (double& x : d) x *= cells;
  // Ghosts: P_-1 = 2 P_0 - P_1 and P_n+1 = 2 P_n - P_n-1 fold into the real points.
  double wf[max_axis_points + 2] = {}, df[max_axis_points + 2] = {};
  for (int k = 0; k < 4; ++k) {
    const int i = c - 1 + k;
    if (i < 0) {
      wf[0] += 2 * w[k]; wf[1] -= w[k];
      df[0] += 2 * d[k]; df[1] -= d[k];
    } else if (i > cells) {
      wf[cells] += 2 * w[k]; wf[cells - 1] -= w[k];
      df[cells] += 2 * d[k]; df[cells - 1] -= d[k];
    } else {
      wf[i] += w[k];
      df[i] += d[k];
    }
  }
  out.first = std::max(0, c - 1);
  const int last = std::min(cells, c + 2);
  out.count = last - out.first + 1;
  for (int k = 0; k < out.count; ++k) {
    out.w[static_cast<std::size_t>(k)] = wf[out.first + k];
    out.dw[static_cast<std::size_t>(k)] = df[out.first + k];
  }
}

}  // namespace

void axis_weights(Basis basis, int count, double s, AxisWeights& out, bool derivatives) {
  switch (basis) {
    case Basis::bernstein: bernstein(count, s, out, derivatives); return;
    case Basis::bspline: bspline(count, s, out); return;
    case Basis::linear: linear(count, s, out); return;
    case Basis::catmull_rom: catmull_rom(count, s, out); return;
  }
}

double rest_coordinate(Basis basis, int count, int i) {
  if (basis != Basis::bspline) return static_cast<double>(i) / (count - 1);
  // Greville abscissa: mean of knots t_{i+1} .. t_{i+p}.
  const int p = degree_of(count);
  double g = 0;
  for (int j = i + 1; j <= i + p; ++j) g += knot(count, p, j);
  return g / p;
}

}  // namespace fest::ffd
