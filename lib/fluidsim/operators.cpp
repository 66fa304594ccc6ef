#include "fluidsim/operators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace fest::fluidsim {

namespace {

// Calls body(row, j, k) for every x-row of the grid, in parallel on large grids.
template <typename Body>
void for_rows(const Layout& L, Body&& body) {
  const int rows = L.size[1] * L.size[2];
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
  for (int r = 0; r < rows; ++r) {
    const int j = r % L.size[1], k = r / L.size[1];
    body(L.index(0, j, k), j, k);
  }
}

// The neighbouring rows of row (j, k) along axis 1 or 2 (folded), with the sign an odd
// field takes there.
struct RowNeighbours {
  std::size_t plus, minus;
  double plus_sign, minus_sign;
};

RowNeighbours row_neighbours(const Layout& L, const AxisNeighbours& nb, int axis, int j, int k) {
  const int c = axis == 1 ? j : k;
  RowNeighbours r;
  r.plus = axis == 1 ? L.index(0, nb.plus[c], k) : L.index(0, j, nb.plus[c]);
  r.minus = axis == 1 ? L.index(0, nb.minus[c], k) : L.index(0, j, nb.minus[c]);
  r.plus_sign = nb.plus_flip[c] ? -1.0 : 1.0;
  r.minus_sign = nb.minus_flip[c] ? -1.0 : 1.0;
  return r;
}

// One row of D u into o[0..nx). Along x the end nodes go through the fold table; the
// interior neighbours are i +- 1 with no sign change (what the table says there), read
// directly so the loop vectorizes.
struct DivergenceRows {
  const Layout& L;
  const Velocity& u;
  double inv2h;
  std::array<AxisNeighbours, 3> nb;

  DivergenceRows(const Layout& layout, const Velocity& vel) : L(layout), u(vel), inv2h(0.5 / layout.h) {
    for (int a = 0; a < L.dim; ++a) nb[a] = neighbours(L, a, 1);
  }

  void row(std::size_t row, int j, int k, double* o) const {
    const int nx = L.size[0];
    const double* ux = u[0].data() + row;
    auto folded = [&](int i) {
      const double up = ux[nb[0].plus[i]] * (nb[0].plus_flip[i] ? -1.0 : 1.0);
      const double um = ux[nb[0].minus[i]] * (nb[0].minus_flip[i] ? -1.0 : 1.0);
      return (up - um) * inv2h;
    };
    o[0] = folded(0);
    for (int i = 1; i < nx - 1; ++i) o[i] = (ux[i + 1] - ux[i - 1]) * inv2h;
    o[nx - 1] = folded(nx - 1);
    for (int a = 1; a < L.dim; ++a) {
      const RowNeighbours r = row_neighbours(L, nb[a], a, j, k);
      const double* p = u[a].data() + r.plus;
      const double* m = u[a].data() + r.minus;
      const double sp = r.plus_sign * inv2h, sm = r.minus_sign * inv2h;
      for (int i = 0; i < nx; ++i) o[i] += sp * p[i] - sm * m[i];
    }
  }
};

// max |v| over v[0..n), or the first non-finite value.
double max_abs(const double* v, std::size_t n) noexcept {
  double m = 0.0;
  bool finite = true;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::fabs(v[i]);
    finite &= a <= std::numeric_limits<double>::max();  // false for inf and NaN
    m = a > m ? a : m;
  }
  if (!finite)
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(v[i])) return v[i];
  return m;
}

}  // namespace

void divergence(const Layout& L, const Velocity& u, Field& out) {
  out.resize(L.count());
  const DivergenceRows D(L, u);
  // Row by row: along x through the fold table, along y and z whole neighbouring rows
  // (a fold across a wall flips the sign of the odd normal component).
  for_rows(L, [&](std::size_t row, int j, int k) { D.row(row, j, k, out.data() + row); });
}

double max_abs_divergence(const Layout& L, const Velocity& u) {
  const DivergenceRows D(L, u);
  const int rows = L.size[1] * L.size[2];
  std::vector<double> row_max(rows);
#pragma omp parallel if (L.count() >= kParallelNodes)
  {
    std::vector<double> o(L.size[0]);
#pragma omp for schedule(static)
    for (int r = 0; r < rows; ++r) {
      const int j = r % L.size[1], k = r / L.size[1];
      D.row(L.index(0, j, k), j, k, o.data());
      row_max[r] = max_abs(o.data(), o.size());
    }
  }
  return max_abs(row_max.data(), row_max.size());  // rows in order: deterministic
}

void subtract_gradient(const Layout& L, const Field& q, Velocity& u) {
  const double inv2h = 0.5 / L.h;
  std::array<AxisNeighbours, 3> nb;
  for (int a = 0; a < L.dim; ++a) nb[a] = neighbours(L, a, 1);
  const int nx = L.size[0];
  for_rows(L, [&](std::size_t row, int j, int k) {
    const double* qr = q.data() + row;
    double* ux = u[0].data() + row;
    // Folded ends through the table, the interior directly (i +- 1 there).
    ux[0] -= (qr[nb[0].plus[0]] - qr[nb[0].minus[0]]) * inv2h;
    for (int i = 1; i < nx - 1; ++i) ux[i] -= (qr[i + 1] - qr[i - 1]) * inv2h;
    ux[nx - 1] -= (qr[nb[0].plus[nx - 1]] - qr[nb[0].minus[nx - 1]]) * inv2h;
    for (int a = 1; a < L.dim; ++a) {
      const RowNeighbours r = row_neighbours(L, nb[a], a, j, k);  // q is even: no sign
      const double* p = q.data() + r.plus;
      const double* m = q.data() + r.minus;
      double* ua = u[a].data() + row;
      for (int i = 0; i < nx; ++i) ua[i] -= (p[i] - m[i]) * inv2h;
    }
  });
}

double max_abs(const Field& f) noexcept {
  // Pieces of 4096 values, combined in index order by the same rule: the first piece that
  // holds a non-finite value gives its first one, as the single scan would.
  constexpr std::size_t kPiece = 4096;
  const std::size_t pieces = (f.size() + kPiece - 1) / kPiece;
  if (f.size() < kParallelNodes) return max_abs(f.data(), f.size());
  std::vector<double> piece_max(pieces);
#pragma omp parallel for schedule(static)
  for (std::size_t p = 0; p < pieces; ++p)
    piece_max[p] = max_abs(f.data() + p * kPiece, std::min(kPiece, f.size() - p * kPiece));
  return max_abs(piece_max.data(), pieces);
}

double node_weight(const Layout& L, int i, int j, int k) noexcept {
  double w = 1.0;
  if (L.is_wall(0, i)) w *= 0.5;
  if (L.is_wall(1, j)) w *= 0.5;
  if (L.is_wall(2, k)) w *= 0.5;
  return w;
}

namespace {
template <typename F>
double weighted_accumulate(const Layout& L, F&& term) {
  double total = 0.0;
  for (int k = 0; k < L.size[2]; ++k)
    for (int j = 0; j < L.size[1]; ++j) {
      double row = 0.0;
      for (int i = 0; i < L.size[0]; ++i) row += node_weight(L, i, j, k) * term(L.index(i, j, k));
      total += row;
    }
  return total;
}
}  // namespace

double weighted_dot(const Layout& L, const Velocity& a, const Velocity& b) {
  return weighted_accumulate(L, [&](std::size_t n) {
    double s = 0.0;
    for (int c = 0; c < L.dim; ++c) s += a[c][n] * b[c][n];
    return s;
  });
}

double kinetic_energy(const Layout& L, const Velocity& u) {
  return 0.5 * weighted_dot(L, u, u) * std::pow(L.h, L.dim);
}

double weighted_sum(const Layout& L, const Field& s) {
  return weighted_accumulate(L, [&](std::size_t n) { return s[n]; }) * std::pow(L.h, L.dim);
}

}  // namespace fest::fluidsim
