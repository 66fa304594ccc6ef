#pragma once
// Synthetic DEMs for the terrainlod tests: planes (analytic) and seeded fBm terrain made by
// midpoint displacement (diamond-square), the classic fractal terrain model.

#include <cmath>
#include <cstdint>
#include <random>

#include "terrainlod/extract.hpp"
#include "terrainlod/height_grid.hpp"

namespace fest::test {

inline terrainlod::HeightGrid plane_grid(int w, int h, double a, double b, double c) {
  terrainlod::HeightGrid g;
  g.width = w;
  g.height = h;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) g.h.push_back(a * i + b * j + c);
  return g;
}

// (2^k + 1)^2 samples, roughness 0.5 per octave (Hurst exponent ~1), heights in metres.
inline terrainlod::HeightGrid fbm_grid(int k, std::uint32_t seed, double amplitude = 100.0) {
  const int n = (1 << k) + 1;
  terrainlod::HeightGrid g;
  g.width = g.height = n;
  g.h.assign(static_cast<std::size_t>(n) * n, 0.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto at = [&](int i, int j) -> double& { return g.h[static_cast<std::size_t>(j) * n + i]; };
  at(0, 0) = amplitude * u(rng), at(n - 1, 0) = amplitude * u(rng);
  at(0, n - 1) = amplitude * u(rng), at(n - 1, n - 1) = amplitude * u(rng);
  double scale = amplitude;
  for (int step = n - 1; step > 1; step /= 2, scale *= 0.5) {
    const int half = step / 2;
    for (int j = half; j < n; j += step)
      for (int i = half; i < n; i += step)
        at(i, j) = 0.25 * (at(i - half, j - half) + at(i + half, j - half) + at(i - half, j + half) +
                           at(i + half, j + half)) + scale * u(rng);
    for (int j = 0; j < n; j += half)
      for (int i = (j / half) % 2 == 0 ? half : 0; i < n; i += step) {
        double sum = 0;
        int cnt = 0;
        if (i >= half) sum += at(i - half, j), ++cnt;
        if (i + half < n) sum += at(i + half, j), ++cnt;
        if (j >= half) sum += at(i, j - half), ++cnt;
        if (j + half < n) sum += at(i, j + half), ++cnt;
        at(i, j) = sum / cnt + scale * u(rng);
      }
  }
  // Integer heights, as in real int16 DEMs (and so plateaus and exact ties occur).
  for (double& z : g.h) z = std::round(z);
  return g;
}

// The layout of the selection tests: a 2^3-tile-wide pyramid (B = 16 cells of 10 m, L = 3).
inline terrainlod::PyramidLayout small_layout() {
  terrainlod::PyramidLayout L;
  L.levels = 3;
  L.texels = 16;
  L.dx = L.dy = 10;
  for (int l = 0; l <= 3; ++l) {
    L.tiles_x.push_back(1 << l);
    L.tiles_y.push_back(1 << l);
    L.cells.push_back(16 << (3 - l));
  }
  return L;
}

}  // namespace fest::test
