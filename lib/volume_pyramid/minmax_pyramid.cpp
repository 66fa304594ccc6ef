#include "volume_pyramid/minmax_pyramid.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel_for.hpp"

namespace fest::volume_pyramid {

ScalarGrid to_grid(const Volume& v, std::size_t& nans) {
  ScalarGrid g;
  g.dims = v.dims;
  g.values.resize(v.size());
  nans = 0;
  for (std::size_t p = 0; p < v.size(); ++p) {
    g.values[p] = static_cast<float>(v.voxels[p]);
    nans += std::isnan(v.voxels[p]);
  }
  g.origin = v.origin;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) g.axes[3 * r + c] = v.direction[3 * r + c] * v.spacing[c];
  return g;
}

ScalarGrid padded(const ScalarGrid& g, float value) {
  ScalarGrid p;
  p.dims = {g.dims[0] + 2, g.dims[1] + 2, g.dims[2] + 2};
  p.values.assign(p.size(), value);
  for (std::size_t k = 0; k < g.dims[2]; ++k)
    for (std::size_t j = 0; j < g.dims[1]; ++j)
      std::copy_n(&g.values[g.index(0, j, k)], g.dims[0], &p.values[p.index(1, j + 1, k + 1)]);
  p.axes = g.axes;
  const auto w = g.world(-1, -1, -1);
  p.origin = w;
  return p;
}

namespace {
std::size_t ceil_div(std::size_t a, std::size_t b) { return (a + b - 1) / b; }
}  // namespace

MinMaxPyramid::MinMaxPyramid(const ScalarGrid& grid, int threads, int finest_level) : finest_(finest_level) {
  const auto& d = grid.dims;
  if (d[0] < 2 || d[1] < 2 || d[2] < 2) return;
  // Finest stored level straight from the samples: block b spans samples
  // [b*s, min((b+1)*s, n-1)] on each axis (closed region).
  const std::size_t s = std::size_t{1} << finest_;
  Level first;
  first.n = {ceil_div(d[0] - 1, s), ceil_div(d[1] - 1, s), ceil_div(d[2] - 1, s)};
  first.lo.resize(first.n[0] * first.n[1] * first.n[2]);
  first.hi.resize(first.lo.size());
  parallel_for(first.n[2], threads, [&](std::size_t bk) {
    const std::size_t k0 = bk * s, k1 = std::min(k0 + s, d[2] - 1);
    for (std::size_t bj = 0; bj < first.n[1]; ++bj) {
      const std::size_t j0 = bj * s, j1 = std::min(j0 + s, d[1] - 1);
      for (std::size_t bi = 0; bi < first.n[0]; ++bi) {
        const std::size_t i0 = bi * s, i1 = std::min(i0 + s, d[0] - 1);
        float lo = grid.values[grid.index(i0, j0, k0)], hi = lo;
        for (std::size_t k = k0; k <= k1; ++k)
          for (std::size_t j = j0; j <= j1; ++j) {
            const float* row = &grid.values[grid.index(0, j, k)];
            for (std::size_t i = i0; i <= i1; ++i) {
              lo = std::min(lo, row[i]);
              hi = std::max(hi, row[i]);
            }
          }
        const std::size_t n = first.index(bi, bj, bk);
        first.lo[n] = lo;
        first.hi[n] = hi;
      }
    }
  });
  levels_.push_back(std::move(first));
  // Coarser levels from 2x2x2 children (closed regions of children cover the parent's).
  while (levels_.back().n[0] > 1 || levels_.back().n[1] > 1 || levels_.back().n[2] > 1) {
    const Level& c = levels_.back();
    Level p;
    p.n = {ceil_div(c.n[0], 2), ceil_div(c.n[1], 2), ceil_div(c.n[2], 2)};
    p.lo.resize(p.n[0] * p.n[1] * p.n[2]);
    p.hi.resize(p.lo.size());
    for (std::size_t k = 0; k < p.n[2]; ++k)
      for (std::size_t j = 0; j < p.n[1]; ++j)
        for (std::size_t i = 0; i < p.n[0]; ++i) {
          float lo = c.lo[c.index(2 * i, 2 * j, 2 * k)], hi = c.hi[c.index(2 * i, 2 * j, 2 * k)];
          for (std::size_t dk = 0; dk < 2; ++dk)
            for (std::size_t dj = 0; dj < 2; ++dj)
              for (std::size_t di = 0; di < 2; ++di) {
                const std::size_t ci = 2 * i + di, cj = 2 * j + dj, ck = 2 * k + dk;
                if (ci >= c.n[0] || cj >= c.n[1] || ck >= c.n[2]) continue;
                lo = std::min(lo, c.lo[c.index(ci, cj, ck)]);
                hi = std::max(hi, c.hi[c.index(ci, cj, ck)]);
              }
          p.lo[p.index(i, j, k)] = lo;
          p.hi[p.index(i, j, k)] = hi;
        }
    levels_.push_back(std::move(p));
  }
}

std::size_t MinMaxPyramid::bytes() const noexcept {
  std::size_t b = 0;
  for (const auto& L : levels_) b += (L.lo.size() + L.hi.size()) * sizeof(float);
  return b;
}

}  // namespace fest::volume_pyramid
