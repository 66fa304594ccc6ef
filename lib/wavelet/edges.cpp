#include "wavelet/edges.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel_for.hpp"

namespace fest::wavelet {

double scale_sigma(int j) noexcept { return std::sqrt((std::pow(4.0, j) - 1.0) / 3.0); }

namespace {

using Dims3 = std::array<std::size_t, 3>;

std::size_t mirror(long i, std::size_t n) {
  if (n == 1) return 0;
  const long period = 2 * static_cast<long>(n) - 2;
  i %= period;
  if (i < 0) i += period;
  if (i >= static_cast<long>(n)) i = period - i;
  return static_cast<std::size_t>(i);
}

// One pass of the a trous cubic B-spline along `axis` with taps `hole` apart.
void smooth_axis(std::vector<double>& v, const Dims3& d, int axis, long hole, int threads) {
  static const double h[5] = {1 / 16.0, 4 / 16.0, 6 / 16.0, 4 / 16.0, 1 / 16.0};
  const std::size_t n = d[static_cast<std::size_t>(axis)];
  if (n == 1) return;
  const std::size_t stride = axis == 0 ? 1 : (axis == 1 ? d[0] : d[0] * d[1]);
  const std::size_t lines = v.size() / n;
  parallel_for(lines, threads, [&](std::size_t l) {
    // Line l's first voxel: decompose l over the two other axes.
    std::size_t base;
    if (axis == 0) base = l * d[0];
    else if (axis == 1) base = (l % d[0]) + (l / d[0]) * d[0] * d[1];
    else base = l;
    std::vector<double> in(n);
    for (std::size_t k = 0; k < n; ++k) in[k] = v[base + k * stride];
    for (std::size_t k = 0; k < n; ++k) {
      double s = 0;
      for (int t = -2; t <= 2; ++t) s += h[t + 2] * in[mirror(static_cast<long>(k) + t * hole, n)];
      v[base + k * stride] = s;
    }
  });
}

struct Gradient {
  std::vector<float> gx, gy, gz, m;
};

Gradient gradient(const std::vector<double>& s, const Dims3& d, double sigma, int threads) {
  Gradient g;
  const std::size_t n = s.size();
  g.gx.resize(n);
  g.gy.resize(n);
  g.gz.resize(n);
  g.m.resize(n);
  const std::size_t sy = d[0], sz = d[0] * d[1];
  parallel_for(d[2], threads, [&](std::size_t z) {
    for (std::size_t y = 0; y < d[1]; ++y)
      for (std::size_t x = 0; x < d[0]; ++x) {
        const std::size_t i = x + y * sy + z * sz;
        auto diff = [&](std::size_t c, std::size_t nc, std::size_t stride) {
          if (nc == 1) return 0.0;
          const std::size_t lo = c > 0 ? i - stride : i, hi = c + 1 < nc ? i + stride : i;
          // Mirror extension makes the derivative vanish at the border.
          if (c == 0 || c + 1 == nc) return 0.0;
          return 0.5 * (s[hi] - s[lo]);
        };
        const double gx = diff(x, d[0], 1) * sigma, gy = diff(y, d[1], sy) * sigma, gz = diff(z, d[2], sz) * sigma;
        g.gx[i] = static_cast<float>(gx);
        g.gy[i] = static_cast<float>(gy);
        g.gz[i] = static_cast<float>(gz);
        g.m[i] = static_cast<float>(std::sqrt(gx * gx + gy * gy + gz * gz));
      }
  });
  return g;
}

// Trilinear interpolation of m at a point in voxel coordinates (clamped to the grid).
double sample(const std::vector<float>& m, const Dims3& d, double px, double py, double pz) {
  const double p[3] = {px, py, pz};
  std::size_t i0[3], i1[3];
  double f[3];
  for (int a = 0; a < 3; ++a) {
    const double hi = static_cast<double>(d[static_cast<std::size_t>(a)] - 1);
    const double c = std::clamp(p[a], 0.0, hi);
    const double fl = std::floor(c);
    i0[a] = static_cast<std::size_t>(fl);
    i1[a] = std::min(i0[a] + 1, d[static_cast<std::size_t>(a)] - 1);
    f[a] = c - fl;
  }
  auto at = [&](std::size_t x, std::size_t y, std::size_t z) { return static_cast<double>(m[x + d[0] * (y + d[1] * z)]); };
  double r = 0;
  for (int c = 0; c < 8; ++c) {
    const std::size_t x = (c & 1) ? i1[0] : i0[0], y = (c & 2) ? i1[1] : i0[1], z = (c & 4) ? i1[2] : i0[2];
    const double w = ((c & 1) ? f[0] : 1 - f[0]) * ((c & 2) ? f[1] : 1 - f[1]) * ((c & 4) ? f[2] : 1 - f[2]);
    if (w != 0) r += w * at(x, y, z);
  }
  return r;
}

}  // namespace

EdgeMap multiscale_edges(const Volume& volume, const EdgeOptions& o) {
  const Dims3 d = volume.dims;
  const std::size_t n = volume.size();
  if (n == 0 || volume.voxels.size() != n) throw bad_input("volume has no voxels");
  std::size_t nonfinite = 0;
  for (double v : volume.voxels) nonfinite += !std::isfinite(v);
  if (nonfinite) throw bad_input("{} voxels are NaN or infinite: edges need finite values", nonfinite);
  const int J = std::clamp(o.scales, 1, 6);
  const int K = o.min_scales <= 0 ? J : std::min(o.min_scales, J);
  const int threads = std::max(1, o.threads);

  std::vector<double> s = volume.voxels;
  std::vector<std::vector<std::uint8_t>> maxima(static_cast<std::size_t>(J));
  std::vector<std::vector<float>> modulus(static_cast<std::size_t>(J));
  std::vector<std::array<float, 3>> offset(n);  // sub-voxel offset of scale-1 maxima
  EdgeMap out;
  const std::size_t sy = d[0], sz = d[0] * d[1];
  // Progress: one pass over the z slices per scale (its smoothing and gradient come before
  // it) and one per chaining step.
  const std::uint64_t passes = static_cast<std::uint64_t>(J + K - 1), slices = d[2];
  std::uint64_t pass = 0;
  for (int j = 1; j <= J; ++j) {
    const long hole = 1L << (j - 1);
    for (int a = 0; a < 3; ++a) smooth_axis(s, d, a, hole, threads);
    Gradient g = gradient(s, d, scale_sigma(j), threads);
    if (j == 1) {
      if (o.threshold >= 0) {
        out.threshold = o.threshold;
      } else {
        // Automatic threshold: 3x the median modulus of the finest scale (the noise
        // floor in textured data), but at least 5% of its largest modulus (so that
        // the round-off ripples of noise-free data never count).
        std::vector<float> sorted = g.m;
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(n / 2), sorted.end());
        const double median = sorted[n / 2];
        const double top = *std::max_element(g.m.begin(), g.m.end());
        out.threshold = std::max(3.0 * median, 0.05 * top);
      }
    }
    auto& mx = maxima[static_cast<std::size_t>(j - 1)];
    mx.assign(n, 0);
    const double threshold = out.threshold;
    ProgressCounter scale_slices(o.progress, slices, pass++ * slices, passes * slices);
    parallel_for(d[2], threads, [&](std::size_t z) {
      scale_slices.step();
      for (std::size_t y = 0; y < d[1]; ++y)
        for (std::size_t x = 0; x < d[0]; ++x) {
          const std::size_t i = x + y * sy + z * sz;
          const double m0 = g.m[i];
          if (m0 <= 0 || m0 < threshold) continue;
          const double ux = g.gx[i] / m0, uy = g.gy[i] / m0, uz = g.gz[i] / m0;
          const double mp = sample(g.m, d, x + ux, y + uy, z + uz);
          const double mm = sample(g.m, d, x - ux, y - uy, z - uz);
          if (!(m0 >= mp && m0 > mm)) continue;
          mx[i] = 1;
          if (j == 1) {
            // Vertex of the parabola through (-1, mm), (0, m0), (1, mp).
            const double den = mm - 2 * m0 + mp;
            const double t = den < 0 ? std::clamp(0.5 * (mm - mp) / den, -0.5, 0.5) : 0.0;
            offset[i] = {static_cast<float>(t * ux), static_cast<float>(t * uy), static_cast<float>(t * uz)};
          }
        }
    });
    scale_slices.finish();
    out.maxima_per_scale.push_back(static_cast<std::size_t>(std::count(mx.begin(), mx.end(), 1)));
    modulus[static_cast<std::size_t>(j - 1)] = std::move(g.m);
  }

  // Chain from the coarsest scale of the required K down to the finest: keep a maximum
  // when a kept one of the next coarser scale lies in its cone of influence. `coarse`
  // holds, for kept maxima, the modulus of the coarser partner (for alpha).
  std::vector<float> partner_modulus(n, 0.f);
  std::vector<std::uint8_t> kept = maxima[static_cast<std::size_t>(K - 1)];
  std::vector<float> alpha_sum(n, 0.f);
  for (int j = K - 1; j >= 1; --j) {
    const long r = 1L << (j - 1);
    const auto& fine = maxima[static_cast<std::size_t>(j - 1)];
    const auto& mfine = modulus[static_cast<std::size_t>(j - 1)];
    const auto& mcoarse = modulus[static_cast<std::size_t>(j)];
    std::vector<std::uint8_t> next(n, 0);
    std::vector<float> next_alpha(n, 0.f);
    const double ratio = std::log2(scale_sigma(j + 1) / scale_sigma(j));
    ProgressCounter chain_slices(o.progress, slices, pass++ * slices, passes * slices);
    parallel_for(d[2], threads, [&](std::size_t z) {
      chain_slices.step();
      for (std::size_t y = 0; y < d[1]; ++y)
        for (std::size_t x = 0; x < d[0]; ++x) {
          const std::size_t i = x + y * sy + z * sz;
          if (!fine[i]) continue;
          double best = -1;
          std::size_t best_i = 0;
          for (long dz = -r; dz <= r; ++dz) {
            const long zz = static_cast<long>(z) + dz;
            if (zz < 0 || zz >= static_cast<long>(d[2])) continue;
            for (long dy = -r; dy <= r; ++dy) {
              const long yy = static_cast<long>(y) + dy;
              if (yy < 0 || yy >= static_cast<long>(d[1])) continue;
              for (long dx = -r; dx <= r; ++dx) {
                const long xx = static_cast<long>(x) + dx;
                if (xx < 0 || xx >= static_cast<long>(d[0])) continue;
                const std::size_t q = static_cast<std::size_t>(xx) + static_cast<std::size_t>(yy) * sy +
                                      static_cast<std::size_t>(zz) * sz;
                if (kept[q] && mcoarse[q] > best) {
                  best = mcoarse[q];
                  best_i = q;
                }
              }
            }
          }
          if (best < 0) continue;
          next[i] = 1;
          const double a = std::log2(std::max(1e-300, best) / std::max(1e-300, static_cast<double>(mfine[i]))) / ratio;
          next_alpha[i] = static_cast<float>(a + alpha_sum[best_i]);
        }
    });
    chain_slices.finish();
    kept = std::move(next);
    alpha_sum = std::move(next_alpha);
  }

  out.modulus.assign(n, 0.0);
  const auto& m1 = modulus[0];
  for (std::size_t z = 0; z < d[2]; ++z)
    for (std::size_t y = 0; y < d[1]; ++y)
      for (std::size_t x = 0; x < d[0]; ++x) {
        const std::size_t i = x + y * sy + z * sz;
        if (!kept[i]) continue;
        out.modulus[i] = m1[i];
        EdgePoint p;
        p.voxel = {x, y, z};
        p.position = {x + static_cast<double>(offset[i][0]), y + static_cast<double>(offset[i][1]),
                      z + static_cast<double>(offset[i][2])};
        p.modulus = m1[i];
        p.alpha = K > 1 ? alpha_sum[i] / static_cast<double>(K - 1) : 0.0;
        out.points.push_back(p);
      }
  return out;
}

}  // namespace fest::wavelet
