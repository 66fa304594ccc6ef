#include "feshape/triangulation.hpp"

#include <cmath>

#include "core/error.hpp"

namespace fest::feshape {

bool is_pole(double u) noexcept { return std::abs(u) >= pi / 2 - 1e-12; }

Triangulation lat_long_mesh(int rings, int meridians) {
  if (rings < 1 || meridians < 3) throw make_error(Status::usage, "a lat-long mesh needs >= 1 ring and >= 3 meridians, got {}x{}", rings, meridians);
  Triangulation t;
  const int n = meridians;
  auto node = [&](int ring, int j) { return 1 + ring * n + ((j % n) + n) % n; };
  t.u.push_back(-pi / 2);  // south pole = node 0
  t.v.push_back(0);
  for (int k = 1; k <= rings; ++k)
    for (int j = 0; j < n; ++j) {
      t.u.push_back(-pi / 2 + k * pi / (rings + 1));
      t.v.push_back(-pi + 2 * pi * j / n);
    }
  const int north = static_cast<int>(t.u.size());
  t.u.push_back(pi / 2);
  t.v.push_back(0);
  // Outward orientation: with x = cos u cos v, y = cos u sin v, z = sin u, increasing v
  // turns counter-clockwise about +z, increasing u goes north.
  for (int j = 0; j < n; ++j) t.tris.push_back({0, node(0, j + 1), node(0, j)});
  for (int k = 0; k + 1 < rings; ++k)
    for (int j = 0; j < n; ++j) {
      const int a = node(k, j), b = node(k, j + 1), c = node(k + 1, j + 1), d = node(k + 1, j);
      if (k % 2 == 0) {
        t.tris.push_back({a, b, c});
        t.tris.push_back({a, c, d});
      } else {
        t.tris.push_back({a, b, d});
        t.tris.push_back({b, c, d});
      }
    }
  for (int j = 0; j < n; ++j) t.tris.push_back({north, node(rings - 1, j), node(rings - 1, j + 1)});
  t.level.assign(t.tris.size(), 0);
  return t;
}

double seam_midpoint_v(double va, double vb) noexcept {
  if (std::abs(va - vb) > pi) (va < vb ? va : vb) += 2 * pi;
  double m = 0.5 * (va + vb);
  if (m >= pi) m -= 2 * pi;
  return m;
}

void edge_midpoint_uv(const Triangulation& t, int a, int b, double& u, double& v) noexcept {
  u = 0.5 * (t.u[a] + t.u[b]);
  const bool pa = is_pole(t.u[a]), pb = is_pole(t.u[b]);
  if (pa && !pb)
    v = t.v[b];
  else if (pb && !pa)
    v = t.v[a];
  else
    v = seam_midpoint_v(t.v[a], t.v[b]);
}

std::array<std::array<double, 2>, 3> unwrapped_corners(const Triangulation& t, int tri) noexcept {
  std::array<std::array<double, 2>, 3> c;
  const auto& f = t.tris[tri];
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i < 3; ++i) {
    c[i] = {t.u[f[i]], t.v[f[i]]};
    if (!is_pole(c[i][0])) {
      lo = std::min(lo, c[i][1]);
      hi = std::max(hi, c[i][1]);
    }
  }
  if (hi - lo > pi)
    for (auto& p : c)
      if (!is_pole(p[0]) && p[1] < 0) p[1] += 2 * pi;
  for (int i = 0; i < 3; ++i)
    if (is_pole(c[i][0])) {
      double sum = 0;
      int count = 0;
      for (int j = 0; j < 3; ++j)
        if (!is_pole(c[j][0])) {
          sum += c[j][1];
          ++count;
        }
      c[i][1] = count ? sum / count : 0.0;
    }
  return c;
}

}  // namespace fest::feshape
