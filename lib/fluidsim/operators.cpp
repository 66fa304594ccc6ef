#include "fluidsim/operators.hpp"

#include <cmath>

namespace fest::fluidsim {

void divergence(const Layout& L, const Velocity& u, Field& out) {
  out.assign(L.count(), 0.0);
  const double inv2h = 0.5 / L.h;
  for (int a = 0; a < L.dim; ++a) {
    const AxisNeighbours nb = neighbours(L, a, 1);
    const Field& ua = u[a];
    // The normal component is odd: a folded neighbour changes sign.
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
    for (int k = 0; k < L.size[2]; ++k)
      for (int j = 0; j < L.size[1]; ++j)
        for (int i = 0; i < L.size[0]; ++i) {
          const int ijk[3] = {i, j, k};
          int p[3] = {i, j, k}, m[3] = {i, j, k};
          p[a] = nb.plus[ijk[a]];
          m[a] = nb.minus[ijk[a]];
          const double up = ua[L.index(p[0], p[1], p[2])] * (nb.plus_flip[ijk[a]] ? -1.0 : 1.0);
          const double um = ua[L.index(m[0], m[1], m[2])] * (nb.minus_flip[ijk[a]] ? -1.0 : 1.0);
          out[L.index(i, j, k)] += (up - um) * inv2h;
        }
  }
}

void subtract_gradient(const Layout& L, const Field& q, Velocity& u) {
  const double inv2h = 0.5 / L.h;
  for (int a = 0; a < L.dim; ++a) {
    const AxisNeighbours nb = neighbours(L, a, 1);
    Field& ua = u[a];
#pragma omp parallel for schedule(static) if (L.count() >= kParallelNodes)
    for (int k = 0; k < L.size[2]; ++k)
      for (int j = 0; j < L.size[1]; ++j)
        for (int i = 0; i < L.size[0]; ++i) {
          const int ijk[3] = {i, j, k};
          int p[3] = {i, j, k}, m[3] = {i, j, k};
          p[a] = nb.plus[ijk[a]];
          m[a] = nb.minus[ijk[a]];
          ua[L.index(i, j, k)] -= (q[L.index(p[0], p[1], p[2])] - q[L.index(m[0], m[1], m[2])]) * inv2h;
        }
  }
}

double max_abs(const Field& f) noexcept {
  double m = 0.0;
  for (double v : f) m = std::fmax(m, std::fabs(v));
  for (double v : f)
    if (!std::isfinite(v)) return v;
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
