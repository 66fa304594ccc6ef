#include "brdffit/separable.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "brdffit/parallel_chunks.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

Eigen::Vector3d grid_direction(int ti, int pi, const SeparableOptions& o) {
  const double theta = (ti + 0.5) * (M_PI / 2) / o.theta_bins;
  const double phi = (pi + 0.5) * (2 * M_PI) / o.phi_bins;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

void half_difference_to_in_out(const Eigen::Vector3d& half, const Eigen::Vector3d& difference, Eigen::Vector3d& in,
                               Eigen::Vector3d& out) {
  // R = Rz(phi_h) Ry(theta_h) takes the pole to h.
  const double theta_h = std::acos(std::clamp(half.z(), -1.0, 1.0));
  const double phi_h = std::atan2(half.y(), half.x());
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(phi_h, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(theta_h, Eigen::Vector3d::UnitY())).toRotationMatrix();
  in = r * difference;
  out = 2 * in.dot(half) * half - in;
}

SeparableFactors factor_brdf(const reflectance::LafortuneBrdf& brdf, SeparableGrid grid, const SeparableOptions& o) {
  if (o.theta_bins < 1 || o.theta_bins > 1024 || o.phi_bins < 1 || o.phi_bins > 1024)
    throw bad_input("grid {}x{}: 1..1024 cells per angle", o.theta_bins, o.phi_bins);
  const std::size_t m = static_cast<std::size_t>(o.theta_bins) * static_cast<std::size_t>(o.phi_bins);
  if (m > 4096) throw bad_input("grid {}x{}: at most 4096 directions (the matrix is their square)", o.theta_bins, o.phi_bins);
  std::vector<Eigen::Vector3d> dirs(m);
  for (int t = 0; t < o.theta_bins; ++t)
    for (int p = 0; p < o.phi_bins; ++p)
      dirs[static_cast<std::size_t>(t) * static_cast<std::size_t>(o.phi_bins) + static_cast<std::size_t>(p)] =
          grid_direction(t, p, o);

  // F (three channels, row-major m x m) and the weights: 1 where both directions are
  // above the surface.
  std::vector<float> f(3 * m * m, 0.f);
  std::vector<std::uint8_t> w(m * m, 0);
  const int threads = std::max(1, o.threads);
  for_each_chunk(m, 16, threads, [&](std::size_t, std::size_t r0, std::size_t r1) {
    for (std::size_t i = r0; i < r1; ++i)
      for (std::size_t j = 0; j < m; ++j) {
        Eigen::Vector3d in, out;
        if (grid == SeparableGrid::half_difference) {
          half_difference_to_in_out(dirs[i], dirs[j], in, out);
        } else {
          out = dirs[i];
          in = dirs[j];
        }
        if (in.z() <= 0 || out.z() <= 0) continue;
        w[i * m + j] = 1;
        const reflectance::Rgb v = reflectance::evaluate(brdf, in, out);
        for (std::size_t c = 0; c < 3; ++c) f[c * m * m + i * m + j] = static_cast<float>(v[static_cast<Eigen::Index>(c)]);
      }
  });

  SeparableFactors r;
  r.grid = grid;
  r.theta_bins = o.theta_bins;
  r.phi_bins = o.phi_bins;
  r.g.assign(m, Eigen::Vector3d::Zero());
  r.h.assign(m, Eigen::Vector3d::Zero());
  double err_all = 0, norm_all = 0;
  for (std::size_t c = 0; c < 3; ++c) {
    const float* fc = &f[c * m * m];
    std::vector<double> g(m, 0.0), h(m, 1.0), next(m);
    double previous = -1, err = 0, norm = 0;
    for (std::size_t k = 0; k < m * m; ++k) norm += w[k] ? static_cast<double>(fc[k]) * fc[k] : 0.0;
    int iter = 0;
    for (; iter < o.max_iterations; ++iter) {
      // g from h (rows), then h from g (columns); every row is independent.
      for_each_chunk(m, 64, threads, [&](std::size_t, std::size_t r0, std::size_t r1) {
        for (std::size_t i = r0; i < r1; ++i) {
          double num = 0, den = 0;
          for (std::size_t j = 0; j < m; ++j)
            if (w[i * m + j]) {
              num += fc[i * m + j] * h[j];
              den += h[j] * h[j];
            }
          g[i] = den > 0 ? num / den : 0;
        }
      });
      for_each_chunk(m, 64, threads, [&](std::size_t, std::size_t c0, std::size_t c1) {
        for (std::size_t j = c0; j < c1; ++j) next[j] = 0;
        std::vector<double> den(c1 - c0, 0.0);
        for (std::size_t i = 0; i < m; ++i)
          for (std::size_t j = c0; j < c1; ++j)
            if (w[i * m + j]) {
              next[j] += fc[i * m + j] * g[i];
              den[j - c0] += g[i] * g[i];
            }
        for (std::size_t j = c0; j < c1; ++j) next[j] = den[j - c0] > 0 ? next[j] / den[j - c0] : 0;
      });
      h.swap(next);
      err = 0;
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j)
          if (w[i * m + j]) {
            const double e = fc[i * m + j] - g[i] * h[j];
            err += e * e;
          }
      if (norm == 0 || err <= 1e-30 * norm) break;
      if (previous >= 0 && std::abs(previous - err) <= o.tolerance * previous) break;
      previous = err;
    }
    r.iterations = std::max(r.iterations, iter + 1);
    // h to mean 1 over the columns that take part, g carries the scale.
    double sum = 0;
    std::size_t used = 0;
    for (std::size_t j = 0; j < m; ++j) {
      bool any = false;
      for (std::size_t i = 0; i < m && !any; ++i) any = w[i * m + j];
      if (any) {
        sum += h[j];
        ++used;
      }
    }
    const double mean = used ? sum / static_cast<double>(used) : 1.0;
    const double scale = mean != 0 ? mean : 1.0;
    for (std::size_t i = 0; i < m; ++i) {
      r.g[i][static_cast<Eigen::Index>(c)] = g[i] * scale;
      r.h[i][static_cast<Eigen::Index>(c)] = h[i] / scale;
    }
    r.relative_rms[static_cast<Eigen::Index>(c)] = norm > 0 ? std::sqrt(err / norm) : 0.0;
    err_all += err;
    norm_all += norm;
  }
  r.relative_rms_all = norm_all > 0 ? std::sqrt(err_all / norm_all) : 0.0;
  return r;
}

}  // namespace fest::brdffit
