#include "fluidsim/render.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fest::fluidsim {

Plane render_plane(const std::vector<double>& field, const std::array<int, 3>& size, int dim,
                   const RenderOptions& o) {
  Plane p;
  if (dim == 2) {
    p.width = size[0];
    p.height = size[1];
    p.values.resize(static_cast<std::size_t>(p.width) * p.height);
    for (int y = 0; y < p.height; ++y)
      for (int x = 0; x < p.width; ++x)
        p.values[static_cast<std::size_t>(p.height - 1 - y) * p.width + x] = field[x + static_cast<std::size_t>(size[0]) * y];
    return p;
  }
  if (o.axis < 0 || o.axis > 2) throw usage_error("viewing axis {} is not 0, 1 or 2", o.axis);
  // Image axes: the two remaining axes in order (u right, v up).
  const int u = o.axis == 0 ? 1 : 0, v = o.axis == 2 ? 1 : 2;
  p.width = size[u];
  p.height = size[v];
  p.values.assign(static_cast<std::size_t>(p.width) * p.height, 0.0);
  const int depth = size[o.axis];
  int slice = o.index < 0 ? depth / 2 : o.index;
  if (o.mode == RenderMode::slice && slice >= depth)
    throw usage_error("slice index {} is out of range [0, {}]", o.index, depth - 1);
  auto at = [&](int a, int b, int c) {
    int ijk[3];
    ijk[u] = a;
    ijk[v] = b;
    ijk[o.axis] = c;
    return field[ijk[0] + static_cast<std::size_t>(size[0]) * (ijk[1] + static_cast<std::size_t>(size[1]) * ijk[2])];
  };
  const double step = o.sigma * o.spacing;
  for (int b = 0; b < p.height; ++b)
    for (int a = 0; a < p.width; ++a) {
      double val = 0.0;
      if (o.mode == RenderMode::slice) {
        val = at(a, b, slice);
      } else if (o.mode == RenderMode::mip) {
        val = -INFINITY;
        for (int c = 0; c < depth; ++c) val = std::max(val, at(a, b, c));
      } else {
        // Front-to-back from the far end of the axis towards the viewer at index 0.
        double optical = 0.0;
        for (int c = 0; c < depth; ++c) {
          const double s = std::max(0.0, at(a, b, c));
          val += step * s * std::exp(-optical);
          optical += step * s;
        }
      }
      p.values[static_cast<std::size_t>(p.height - 1 - b) * p.width + a] = val;
    }
  return p;
}

std::array<double, 3> colour(Colormap map, double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  if (map == Colormap::gray) return {t, t, t};
  if (map == Colormap::velocity) {
    // Blue (0) - white (0.5) - red (1).
    if (t < 0.5) {
      const double s = t / 0.5;
      return {0.23 + 0.77 * s, 0.30 + 0.70 * s, 0.75 + 0.25 * s};
    }
    const double s = (t - 0.5) / 0.5;
    return {1.0 - 0.3 * s, 1.0 - 0.98 * s, 1.0 - 0.85 * s};
  }
  // Inferno, sampled at nine points and interpolated linearly.
  static const double k[9][3] = {{0.0015, 0.0005, 0.0139}, {0.0874, 0.0446, 0.2248}, {0.2582, 0.0386, 0.4065},
                                 {0.4163, 0.0902, 0.4329}, {0.5783, 0.1480, 0.4044}, {0.7357, 0.2159, 0.3302},
                                 {0.8650, 0.3168, 0.2261}, {0.9545, 0.4687, 0.0999}, {0.9884, 0.9984, 0.6449}};
  const double x = t * 8.0;
  const int i = std::min(7, static_cast<int>(x));
  const double f = x - i;
  return {k[i][0] + f * (k[i + 1][0] - k[i][0]), k[i][1] + f * (k[i + 1][1] - k[i][1]),
          k[i][2] + f * (k[i + 1][2] - k[i][2])};
}

}  // namespace fest::fluidsim
