// Location and shape operators (see shape.hpp).
#include "segbrain/shape.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

#include "segbrain/morphology.hpp"
#include "segbrain/parallel.hpp"

namespace fest::segbrain {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

Point centroid_mm(const Grid& g, const Mask& m) {
  double s[3] = {0, 0, 0};
  std::size_t n = 0;
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y) {
      const std::uint8_t* row = m.data() + g.index(0, y, z);
      for (std::size_t x = 0; x < g.n[0]; ++x)
        if (row[x]) s[0] += double(x), s[1] += double(y), s[2] += double(z), ++n;
    }
  if (!n) return {kNaN, kNaN, kNaN};
  return {s[0] / double(n) * g.spacing[0], s[1] / double(n) * g.spacing[1], s[2] / double(n) * g.spacing[2]};
}

std::array<double, 6> bbox_mm(const Grid& g, const Mask& m) {
  std::array<std::size_t, 3> lo = g.n, hi{0, 0, 0};
  bool any = false;
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y) {
      const std::uint8_t* row = m.data() + g.index(0, y, z);
      for (std::size_t x = 0; x < g.n[0]; ++x)
        if (row[x]) {
          any = true;
          const std::size_t p[3] = {x, y, z};
          for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
        }
    }
  if (!any) return {kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
  std::array<double, 6> b{};
  for (int a = 0; a < 3; ++a) b[2 * a] = double(lo[a]) * g.spacing[a], b[2 * a + 1] = double(hi[a]) * g.spacing[a];
  return b;
}

Mask halfspace(const Grid& g, int axis, bool below, double value_mm) {
  // Which positions along the axis are in; then whole rows are copied or filled.
  Mask in(g.n[axis]);
  for (std::size_t k = 0; k < in.size(); ++k) {
    const double v = double(k) * g.spacing[axis];
    in[k] = below ? v < value_mm : v > value_mm;
  }
  Mask out(g.size());
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y) {
      std::uint8_t* row = out.data() + g.index(0, y, z);
      if (axis == 0) std::copy(in.begin(), in.end(), row);
      else std::fill(row, row + g.n[0], in[axis == 1 ? y : z]);
    }
  return out;
}

Mask components_near(const Grid& g, const Mask& m, int conn, double min_ml, const Point& near, double max_dist_mm) {
  Components c = connected_components(g, m, conn);
  const std::size_t k = c.size.size();
  std::vector<double> sx(k, 0), sy(k, 0), sz(k, 0);
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x)
        if (std::uint32_t id = c.label[g.index(x, y, z)]) sx[id] += double(x), sy[id] += double(y), sz[id] += double(z);
  std::vector<std::uint8_t> keep(k, 0);
  for (std::size_t id = 1; id < k; ++id) {
    const double n = double(c.size[id]);
    if (n * g.voxel_ml() < min_ml) continue;
    const double dx = sx[id] / n * g.spacing[0] - near[0], dy = sy[id] / n * g.spacing[1] - near[1],
                 dz = sz[id] / n * g.spacing[2] - near[2];
    keep[id] = std::sqrt(dx * dx + dy * dy + dz * dz) <= max_dist_mm;
  }
  Mask out(m.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = keep[c.label[i]];
  return out;
}

Mask components_sized(const Grid& g, const Mask& m, int conn, double min_ml, double max_ml) {
  Components c = connected_components(g, m, conn);
  std::vector<std::uint8_t> keep(c.size.size(), 0);
  for (std::size_t id = 1; id < c.size.size(); ++id) {
    const double ml = double(c.size[id]) * g.voxel_ml();
    keep[id] = ml >= min_ml && ml <= max_ml;
  }
  Mask out(m.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = keep[c.label[i]];
  return out;
}

Mask symmetric_pair(const Grid& g, const Mask& m, int conn, double plane_r_mm, double min_dist_mm, double max_dist_mm,
                    double& score_mm) {
  Components c = connected_components(g, m, conn);
  const std::size_t k = c.size.size();
  std::vector<Point> cen(k, Point{0, 0, 0});
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x)
        if (std::uint32_t id = c.label[g.index(x, y, z)]) cen[id][0] += double(x), cen[id][1] += double(y), cen[id][2] += double(z);
  for (std::size_t id = 1; id < k; ++id)
    for (int a = 0; a < 3; ++a) cen[id][a] = cen[id][a] / double(c.size[id]) * g.spacing[a];
  score_mm = std::numeric_limits<double>::infinity();
  std::size_t bi = 0, bj = 0;
  for (std::size_t i = 1; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j) {
      const double dr = std::abs(cen[i][0] - cen[j][0]);
      if (dr < min_dist_mm || dr > max_dist_mm) continue;
      const double s = std::abs(0.5 * (cen[i][0] + cen[j][0]) - plane_r_mm) + std::abs(cen[i][1] - cen[j][1]) +
                       std::abs(cen[i][2] - cen[j][2]);
      if (s < score_mm) score_mm = s, bi = i, bj = j;
    }
  Mask out(m.size());
  if (bi)
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = c.label[i] == bi || c.label[i] == bj;
  return out;
}

Mask geodesic_dilate(const Grid& g, const Mask& m, const Mask& within, double r_mm) {
  // Dijkstra over 26-neighbour steps restricted to `within`, cut at r_mm.
  std::vector<float> dist(g.size(), std::numeric_limits<float>::infinity());
  using Item = std::pair<float, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i]) dist[i] = 0, queue.push({0.0f, i});
  const std::size_t nx = g.n[0], ny = g.n[1], nz = g.n[2];
  while (!queue.empty()) {
    auto [d, i] = queue.top();
    queue.pop();
    if (d > dist[i]) continue;
    const std::size_t x = i % nx, y = (i / nx) % ny, z = i / (nx * ny);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (!dx && !dy && !dz) continue;
          if ((dx < 0 && x == 0) || (dx > 0 && x + 1 == nx) || (dy < 0 && y == 0) || (dy > 0 && y + 1 == ny) ||
              (dz < 0 && z == 0) || (dz > 0 && z + 1 == nz))
            continue;
          const std::size_t j = g.index(x + dx, y + dy, z + dz);
          if (!within[j]) continue;
          const double step = std::sqrt(dx * dx * g.spacing[0] * g.spacing[0] + dy * dy * g.spacing[1] * g.spacing[1] +
                                        dz * dz * g.spacing[2] * g.spacing[2]);
          const float nd = static_cast<float>(d + step);
          if (nd <= r_mm && nd < dist[j]) dist[j] = nd, queue.push({nd, j});
        }
  }
  Mask out(m.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = dist[i] <= r_mm;
  return out;
}

double mirror_dice(const Grid& g, const Mask& m, double plane_r_mm) {
  std::size_t n = 0, both = 0;
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x) {
        if (!m[g.index(x, y, z)]) continue;
        ++n;
        // Mirror position, rounded to the nearest voxel of the same row.
        const double xm = std::round((2 * plane_r_mm - double(x) * g.spacing[0]) / g.spacing[0]);
        if (xm >= 0 && xm < double(g.n[0]) && m[g.index(static_cast<std::size_t>(xm), y, z)]) ++both;
      }
  return n ? double(both) / double(n) : 1.0;  // |M ∧ mirror(M)| twice over |M| + |mirror(M)| = 2|M|
}

}  // namespace fest::segbrain

namespace fest::segbrain {

double midsagittal_r_mm(const Grid& g, const Image& img, const Mask& m, double search_mm) {
  const Point c = centroid_mm(g, m);
  if (std::isnan(c[0])) return kNaN;
  double mean = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i]) mean += img[i], ++n;
  mean /= double(n);
  const double step = g.spacing[0] / 2;
  // Every other voxel row is enough for a correlation over a whole head; each row is
  // visited only between its first and last mask voxel.
  struct Row {
    std::size_t base, x0, x1;  // [x0, x1]
  };
  std::vector<Row> rows;
  for (std::size_t z = 0; z < g.n[2]; z += 2)
    for (std::size_t y = 0; y < g.n[1]; y += 2) {
      const std::size_t base = g.index(0, y, z);
      std::size_t x0 = 0, x1 = g.n[0];
      while (x0 < g.n[0] && !m[base + x0]) ++x0;
      if (x0 == g.n[0]) continue;
      while (!m[base + x1 - 1]) --x1;
      rows.push_back({base, x0, x1 - 1});
    }
  std::vector<double> planes;
  for (double plane = c[0] - search_mm; plane <= c[0] + search_mm + 1e-9; plane += step) planes.push_back(plane);
  // Planes are independent: each thread scores a band of them, every sum in voxel order.
  std::vector<double> score(planes.size());
  parallel_bands(planes.size(), 1, [&](std::size_t, std::size_t p0, std::size_t p1) {
    for (std::size_t p = p0; p < p1; ++p) {
      // Mirror of index x about the plane: 2 plane / spacing - x, an integer on half steps.
      const long long twice = std::llround(2 * planes[p] / g.spacing[0]);
      double sab = 0, saa = 0, sbb = 0;
      for (const Row& row : rows)
        for (std::size_t x = row.x0; x <= row.x1; ++x) {
          const std::size_t i = row.base + x;
          if (!m[i]) continue;
          const long long xm = twice - static_cast<long long>(x);
          if (xm < 0 || xm >= static_cast<long long>(g.n[0])) continue;
          const std::size_t j = row.base + static_cast<std::size_t>(xm);
          if (!m[j]) continue;
          const double va = img[i] - mean, vb = img[j] - mean;
          sab += va * vb, saa += va * va, sbb += vb * vb;
        }
      score[p] = saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : -1;
    }
  });
  double best = -2, best_c = c[0];
  for (std::size_t p = 0; p < planes.size(); ++p)
    if (score[p] > best) best = score[p], best_c = double(std::llround(2 * planes[p] / g.spacing[0])) * g.spacing[0] / 2;
  return best_c;
}

}  // namespace fest::segbrain
