#include "fluidsim/operators.hpp"

#include <cmath>

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

}  // namespace

void divergence(const Layout& L, const Velocity& u, Field& out) {
  out.assign(L.count(), 0.0);
  const double inv2h = 0.5 / L.h;
  std::array<AxisNeighbours, 3> nb;
  for (int a = 0; a < L.dim; ++a) nb[a] = neighbours(L, a, 1);
  const int nx = L.size[0];
  // Row by row: along x through the fold table, along y and z whole neighbouring rows
  // (a fold across a wall flips the sign of the odd normal component).
  for_rows(L, [&](std::size_t row, int j, int k) {
    double* o = out.data() + row;
    const double* ux = u[0].data() + row;
    for (int i = 0; i < nx; ++i) {
      const double up = ux[nb[0].plus[i]] * (nb[0].plus_flip[i] ? -1.0 : 1.0);
      const double um = ux[nb[0].minus[i]] * (nb[0].minus_flip[i] ? -1.0 : 1.0);
      o[i] = (up - um) * inv2h;
    }
    for (int a = 1; a < L.dim; ++a) {
      const RowNeighbours r = row_neighbours(L, nb[a], a, j, k);
      const double* p = u[a].data() + r.plus;
      const double* m = u[a].data() + r.minus;
      const double sp = r.plus_sign * inv2h, sm = r.minus_sign * inv2h;
      for (int i = 0; i < nx; ++i) o[i] += sp * p[i] - sm * m[i];
    }
  });
}

void subtract_gradient(const Layout& L, const Field& q, Velocity& u) {
  const double inv2h = 0.5 / L.h;
  std::array<AxisNeighbours, 3> nb;
  for (int a = 0; a < L.dim; ++a) nb[a] = neighbours(L, a, 1);
  const int nx = L.size[0];
  for_rows(L, [&](std::size_t row, int j, int k) {
    const double* qr = q.data() + row;
    double* ux = u[0].data() + row;
    for (int i = 0; i < nx; ++i) ux[i] -= (qr[nb[0].plus[i]] - qr[nb[0].minus[i]]) * inv2h;
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
  double m = 0.0;
  for (double v : f) {
    if (!std::isfinite(v)) return v;
    m = std::fmax(m, std::fabs(v));
  }
  return m;
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
