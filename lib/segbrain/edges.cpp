// Laplacian of Gaussian and Marr-Hildreth zero crossings.
#include "segbrain/edges.hpp"

#include <algorithm>
#include <cmath>

#include "segbrain/derivatives.hpp"

namespace fest::segbrain {

Image laplacian_of_gaussian(const Grid& g, const Image& img, double sigma_mm, bool in_plane) {
  const int axes = in_plane ? 2 : 3;
  const bool skip[3] = {false, false, in_plane};
  Image sum(img.size(), 0.0f);
  for (int a = 0; a < axes; ++a) {
    int orders[3] = {0, 0, 0};
    orders[a] = 2;
    Image d2 = gaussian_derivative(g, img, sigma_mm, orders, skip);
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += d2[i];
  }
  return sum;
}

Mask zero_crossings(const Grid& g, const Image& log, double slope, bool in_plane) {
  float peak = 0;
  for (float v : log) peak = std::max(peak, std::abs(v));
  const double min_jump = slope * peak;
  // |LoG| below this is zero: where an edge's response ends in a perfectly flat region
  // (zero-filled background) rounding leaves +-1e-16, whose sign would make a crossing
  // with a full-size jump.
  const double zero = 1e-6 * peak;
  Mask edges(g.size(), 0);
  const std::size_t strides[3] = {1, g.n[0], g.n[0] * g.n[1]};
  // Each neighbour pair is seen once, from its lower voxel p towards q = p + e_axis.
  for (std::size_t z = 0; z < g.n[2]; ++z)
    for (std::size_t y = 0; y < g.n[1]; ++y)
      for (std::size_t x = 0; x < g.n[0]; ++x) {
        const std::size_t p = g.index(x, y, z);
        const std::size_t c[3] = {x, y, z};
        for (int a = 0; a < (in_plane ? 2 : 3); ++a) {
          if (c[a] + 1 >= g.n[a]) continue;
          const std::size_t q = p + strides[a];
          const double lp = log[p], lq = log[q];
          if (!((lp > zero && lq < -zero) || (lp < -zero && lq > zero)) || std::abs(lp - lq) < min_jump) continue;
          edges[std::abs(lq) < std::abs(lp) ? q : p] = 1;
        }
        // A crossing exactly on a voxel (its |LoG| in the zero band, its two neighbours
        // along an axis of opposite signs) marks that voxel.
        if (std::abs(log[p]) > zero) continue;
        for (int a = 0; a < (in_plane ? 2 : 3); ++a) {
          if (c[a] == 0 || c[a] + 1 >= g.n[a]) continue;
          const double lm = log[p - strides[a]], lq = log[p + strides[a]];
          if (((lm > zero && lq < -zero) || (lm < -zero && lq > zero)) && std::abs(lm - lq) >= min_jump) edges[p] = 1;
        }
      }
  return edges;
}

Mask marr_hildreth(const Grid& g, const Image& img, double sigma_mm, double slope, bool in_plane) {
  return zero_crossings(g, laplacian_of_gaussian(g, img, sigma_mm, in_plane), slope, in_plane);
}

}  // namespace fest::segbrain
