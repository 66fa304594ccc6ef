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

namespace brdffit_test {

// A lumitexel set made in memory: lumitexel i has a random normal and `per` samples of
// brdf_of(i) from random light and view directions around that normal (half near the
// mirror direction), with multiplicative noise.
template <typename BrdfOf>
fest::brdffit::LumitexelSet make_set(int count, int per, unsigned seed, double noise, BrdfOf brdf_of,
                                     std::vector<Vector3d>* true_normals = nullptr) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, 1);
  fest::brdffit::LumitexelSet set;
  for (int i = 0; i < count; ++i) {
    Vector3d n(g(rng), g(rng), g(rng));
    n.normalize();
    const Eigen::Matrix3d frame = fest::reflectance::local_frame(n);
    fest::brdffit::Lumitexel l;
    l.n = n.cast<float>();
    l.first_sample = set.samples.size();
    l.count = static_cast<std::uint16_t>(per);
    const fest::reflectance::LafortuneBrdf b = brdf_of(i);
    for (int k = 0; k < per; ++k) {
      const Vector3d u = hemisphere(rng, 0.1);
      const Vector3d v = (k % 2) ? near_mirror(rng, u, 0.3, 0.1) : hemisphere(rng, 0.1);
      Vector3d r = evaluate(b, u, v) * u.z();
      for (int c = 0; c < 3; ++c) r[c] *= 1 + noise * g(rng);
      fest::brdffit::Sample s;
      s.image = static_cast<std::uint16_t>(k);
      s.u_world = (frame * u).cast<float>();
      s.v_world = (frame * v).cast<float>();
      s.r = r.cast<float>();
      set.samples.push_back(s);
    }
    set.lumitexels.push_back(l);
    if (true_normals) true_normals->push_back(n);
  }
  return set;
}

// Three distinct materials: a red matte with a broad lobe, a shiny blue, a grey metal-like.
inline std::vector<fest::reflectance::LafortuneBrdf> three_materials() {
  using fest::reflectance::LafortuneBrdf;
  using fest::reflectance::LafortuneLobe;
  using fest::reflectance::Rgb;
  LafortuneBrdf a, b, c;
  a.rho_d = Rgb(0.7, 0.15, 0.1);
  a.lobes = {LafortuneLobe{Rgb::Constant(-0.8), Rgb::Constant(0.8), Rgb::Constant(5)}};
  b.rho_d = Rgb(0.05, 0.1, 0.5);
  b.lobes = {LafortuneLobe{Rgb::Constant(-1.02), Rgb::Constant(1.02), Rgb::Constant(60)}};
  c.rho_d = Rgb(0.2, 0.2, 0.2);
  c.lobes = {LafortuneLobe{Rgb::Constant(-1.05), Rgb::Constant(1.0), Rgb::Constant(20)}};
  return {a, b, c};
}

}  // namespace brdffit_test
