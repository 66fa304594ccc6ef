#pragma once
// Known-answer data for the brdffit unit tests: random directions and exact (or noisy)
// radiance samples r = f_r(u, v) u_z of a known Lafortune BRDF.

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "brdffit/fit_sample.hpp"
#include "reflectance/lafortune.hpp"

namespace brdffit_test {

using Eigen::Vector3d;

// Uniform on the hemisphere z >= zmin.
inline Vector3d hemisphere(std::mt19937_64& rng, double zmin = 0.05) {
  std::uniform_real_distribution<double> u01(0, 1);
  for (;;) {
    const double z = u01(rng), phi = 2 * M_PI * u01(rng);
    if (z < zmin) continue;
    const double s = std::sqrt(1 - z * z);
    return Vector3d(s * std::cos(phi), s * std::sin(phi), z);
  }
}

// A direction near the mirror of u (perturbed by up to `spread` radians), kept above zmin.
inline Vector3d near_mirror(std::mt19937_64& rng, const Vector3d& u, double spread, double zmin = 0.05) {
  std::normal_distribution<double> g(0, spread);
  for (;;) {
    Vector3d v = Vector3d(-u.x(), -u.y(), u.z()) + Vector3d(g(rng), g(rng), g(rng));
    v.normalize();
    if (v.z() >= zmin) return v;
  }
}

// n samples of brdf, half with the view direction near the mirror direction (where the
// lobes live), half uniform; multiplicative Gaussian noise of relative size `noise`,
// additive Gaussian noise of standard deviation `additive`.
inline std::vector<fest::brdffit::FitSample> samples_of(const fest::reflectance::LafortuneBrdf& brdf, int n,
                                                        unsigned seed, double noise = 0, double additive = 0) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::vector<fest::brdffit::FitSample> out;
  for (int i = 0; i < n; ++i) {
    const Vector3d u = hemisphere(rng);
    const Vector3d v = (i % 2) ? near_mirror(rng, u, 0.25) : hemisphere(rng);
    Vector3d r = evaluate(brdf, u, v) * u.z();
    if (noise > 0)
      for (int c = 0; c < 3; ++c) r[c] *= 1 + noise * g(rng);
    if (additive > 0)
      for (int c = 0; c < 3; ++c) r[c] += additive * g(rng);
    out.push_back(fest::brdffit::make_fit_sample(u, v, r));
  }
  return out;
}

// Relative RMS difference of two BRDFs (all channels, f u_z) on a fixed grid of
// directions that none of the random sample sets contains.
inline double relative_rms(const fest::reflectance::LafortuneBrdf& a, const fest::reflectance::LafortuneBrdf& b) {
  double num = 0, den = 0;
  for (int ti = 0; ti < 9; ++ti)
    for (int to = 0; to < 9; ++to)
      for (int po = 0; po < 12; ++po) {
        const double thi = (ti + 0.5) * 0.16, tho = (to + 0.5) * 0.16, pho = (po + 0.5) * M_PI / 6;
        const Vector3d u(std::sin(thi), 0, std::cos(thi));
        const Vector3d v(std::sin(tho) * std::cos(pho), std::sin(tho) * std::sin(pho), std::cos(tho));
        const Vector3d d = (evaluate(a, u, v) - evaluate(b, u, v)) * u.z();
        num += d.squaredNorm();
        den += (evaluate(b, u, v) * u.z()).squaredNorm();
      }
  return std::sqrt(num / den);
}

}  // namespace brdffit_test
