#include "sampling/slope_pyramid.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "sampling/resize.hpp"

namespace fest::sampling {

namespace {

// Unit normal of a slope pair.
void normal_of(double sx, double sy, float* n) {
  const double len = std::sqrt(sx * sx + sy * sy + 1);
  n[0] = static_cast<float>(-sx / len);
  n[1] = static_cast<float>(-sy / len);
  n[2] = static_cast<float>(1 / len);
}

FloatImage half(const FloatImage& img, int threads) {
  ResizeOptions o;
  o.kernel = make_kernel("box");
  o.clamp = ClampMode::none;
  o.threads = threads;
  return resize_working(img, std::max(1, img.width / 2), std::max(1, img.height / 2), o);
}

}  // namespace

FloatImage slopes_from_height(const FloatImage& h, double scale) {
  if (h.width < 1 || h.height < 1) throw bad_input("height map is empty");
  if (!std::isfinite(scale)) throw usage_error("height scale {} is not finite", scale);
  FloatImage s(h.width, h.height, 2);
  auto at = [&](int x, int y) {
    x = (x % h.width + h.width) % h.width;
    y = (y % h.height + h.height) % h.height;
    return static_cast<double>(h.row(y)[static_cast<std::size_t>(x) * static_cast<std::size_t>(h.channels)]);
  };
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      // The surface z = h(x, y) has normal ∝ (−h_x, −h_y, 1): its slopes are the gradient.
      s.row(y)[2 * x] = static_cast<float>(scale * (at(x + 1, y) - at(x - 1, y)) / 2);
      s.row(y)[2 * x + 1] = static_cast<float>(scale * (at(x, y + 1) - at(x, y - 1)) / 2);
    }
  return s;
}

FloatImage slopes_from_normals(const FloatImage& n) {
  if (n.channels < 3) throw bad_input("a normal map needs 3 channels (got {})", n.channels);
  FloatImage s(n.width, n.height, 2);
  for (int y = 0; y < n.height; ++y)
    for (int x = 0; x < n.width; ++x) {
      const float* p = n.row(y) + static_cast<std::size_t>(x) * static_cast<std::size_t>(n.channels);
      if (!(p[2] > 1e-6f)) throw bad_input("normal map: n_z = {} at ({}, {}) does not face outwards", p[2], x, y);
      s.row(y)[2 * x] = -p[0] / p[2];
      s.row(y)[2 * x + 1] = -p[1] / p[2];
    }
  return s;
}

std::vector<SlopeLevel> slope_pyramid(const FloatImage& slopes, bool naive, int threads) {
  if (slopes.channels != 2) throw bad_input("slope pyramid: need 2 slope channels");
  const std::size_t pixels = static_cast<std::size_t>(slopes.width) * static_cast<std::size_t>(slopes.height);
  // Working image: naive -> the unit normals; else the five moments sx, sy, sx², sx·sy, sy².
  FloatImage level(slopes.width, slopes.height, naive ? 3 : 5);
  for (std::size_t i = 0; i < pixels; ++i) {
    const double sx = slopes.data[2 * i], sy = slopes.data[2 * i + 1];
    float* d = level.data.data() + i * static_cast<std::size_t>(level.channels);
    if (naive) {
      normal_of(sx, sy, d);
    } else {
      d[0] = static_cast<float>(sx);
      d[1] = static_cast<float>(sy);
      d[2] = static_cast<float>(sx * sx);
      d[3] = static_cast<float>(sx * sy);
      d[4] = static_cast<float>(sy * sy);
    }
  }
  std::vector<SlopeLevel> out;
  for (;;) {
    SlopeLevel l{FloatImage(level.width, level.height, 3), FloatImage(level.width, level.height, 3)};
    const std::size_t n = static_cast<std::size_t>(level.width) * static_cast<std::size_t>(level.height);
    for (std::size_t i = 0; i < n; ++i) {
      const float* m = level.data.data() + i * static_cast<std::size_t>(level.channels);
      float* nrm = l.normal.data.data() + 3 * i;
      if (naive) {
        const double len = std::sqrt(double(m[0]) * m[0] + double(m[1]) * m[1] + double(m[2]) * m[2]);
        for (int c = 0; c < 3; ++c) nrm[c] = len > 0 ? static_cast<float>(m[c] / len) : (c == 2 ? 1.0f : 0.0f);
        continue;  // covariance stays 0: the naive pyramid has no place for it
      }
      normal_of(m[0], m[1], nrm);
      float* cov = l.covariance.data.data() + 3 * i;
      cov[0] = static_cast<float>(double(m[2]) - double(m[0]) * m[0]);
      cov[1] = static_cast<float>(double(m[3]) - double(m[0]) * m[1]);
      cov[2] = static_cast<float>(double(m[4]) - double(m[1]) * m[1]);
    }
    out.push_back(std::move(l));
    if (level.width == 1 && level.height == 1) break;
    level = half(level, threads);
  }
  return out;
}

}  // namespace fest::sampling
