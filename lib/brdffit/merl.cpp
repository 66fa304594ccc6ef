#include "brdffit/merl.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fest::brdffit {

namespace {

constexpr double kHalfPi = M_PI / 2;

int clampi(int v, int hi) { return std::min(hi - 1, std::max(0, v)); }

Eigen::Vector3d rotate_y(const Eigen::Vector3d& a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * a.x() + s * a.z(), a.y(), -s * a.x() + c * a.z()};
}
Eigen::Vector3d rotate_z(const Eigen::Vector3d& a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * a.x() - s * a.y(), s * a.x() + c * a.y(), a.z()};
}

}  // namespace

int merl_theta_h_index(double theta_h) {
  if (theta_h <= 0) return 0;
  // Square-root warp: more cells near the specular peak.
  const double t = std::sqrt(theta_h / kHalfPi * kMerlThetaH * kMerlThetaH);
  return clampi(static_cast<int>(t), kMerlThetaH);
}

int merl_theta_d_index(double theta_d) { return clampi(static_cast<int>(theta_d / kHalfPi * kMerlThetaD), kMerlThetaD); }

int merl_phi_d_index(double phi_d) {
  if (phi_d < 0) phi_d += M_PI;  // reciprocity
  return clampi(static_cast<int>(phi_d / M_PI * kMerlPhiD), kMerlPhiD);
}

std::size_t merl_cell(double th, double td, double pd) {
  return static_cast<std::size_t>(merl_phi_d_index(pd)) + static_cast<std::size_t>(merl_theta_d_index(td)) * kMerlPhiD +
         static_cast<std::size_t>(merl_theta_h_index(th)) * kMerlPhiD * kMerlThetaD;
}

void half_diff(const Eigen::Vector3d& u, const Eigen::Vector3d& v, double* th, double* td, double* pd) {
  const Eigen::Vector3d h = (u + v).normalized();
  *th = std::acos(std::clamp(h.z(), -1.0, 1.0));
  const double ph = std::atan2(h.y(), h.x());
  const Eigen::Vector3d d = rotate_y(rotate_z(u, -ph), -*th);
  *td = std::acos(std::clamp(d.z(), -1.0, 1.0));
  *pd = std::atan2(d.y(), d.x());
  if (*pd < 0) *pd += M_PI;  // isotropy + reciprocity: phi_d and phi_d + pi are the same cell
  if (*pd >= M_PI) *pd -= M_PI;
}

void merl_cell_directions(int ith, int itd, int ipd, Eigen::Vector3d* u, Eigen::Vector3d* v) {
  const double f = (ith + 0.5) / kMerlThetaH;
  const double th = f * f * kHalfPi;  // inverse of the square-root warp
  const double td = (itd + 0.5) / kMerlThetaD * kHalfPi;
  const double pd = (ipd + 0.5) / kMerlPhiD * M_PI;
  const Eigen::Vector3d d(std::sin(td) * std::cos(pd), std::sin(td) * std::sin(pd), std::cos(td));
  *u = rotate_y(d, th);
  *v = rotate_y(Eigen::Vector3d(-d.x(), -d.y(), d.z()), th);
}

Eigen::Vector3d merl_lookup(const MerlTable& t, const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  double th, td, pd;
  half_diff(u, v, &th, &td, &pd);
  const std::size_t i = merl_cell(th, td, pd);
  return {t.values[i] * kMerlScale[0], t.values[i + kMerlCells] * kMerlScale[1], t.values[i + 2 * kMerlCells] * kMerlScale[2]};
}

MerlTable merl_from_brdf(const reflectance::LafortuneBrdf& brdf) {
  MerlTable t;
  t.values.assign(3 * kMerlCells, -1.0);
  for (int a = 0; a < kMerlThetaH; ++a)
    for (int b = 0; b < kMerlThetaD; ++b)
      for (int c = 0; c < kMerlPhiD; ++c) {
        Eigen::Vector3d u, v;
        merl_cell_directions(a, b, c, &u, &v);
        const std::size_t i = static_cast<std::size_t>(c) + static_cast<std::size_t>(b) * kMerlPhiD +
                              static_cast<std::size_t>(a) * kMerlPhiD * kMerlThetaD;
        if (u.z() <= 0 || v.z() <= 0) continue;  // below the horizon: unmeasured, as in MERL
        const reflectance::Rgb f = evaluate(brdf, u, v);
        for (int ch = 0; ch < 3; ++ch) t.values[i + static_cast<std::size_t>(ch) * kMerlCells] = f[ch] / kMerlScale[ch];
      }
  return t;
}

std::vector<FitSample> merl_samples(const MerlTable& t) {
  if (t.values.size() != 3 * kMerlCells) throw bad_input("MERL table has {} values, expected {}", t.values.size(), 3 * kMerlCells);
  std::vector<FitSample> out;
  for (int a = 0; a < kMerlThetaH; ++a)
    for (int b = 0; b < kMerlThetaD; ++b)
      for (int c = 0; c < kMerlPhiD; ++c) {
        const std::size_t i = static_cast<std::size_t>(c) + static_cast<std::size_t>(b) * kMerlPhiD +
                              static_cast<std::size_t>(a) * kMerlPhiD * kMerlThetaD;
        Eigen::Vector3d f;
        bool ok = true;
        for (int ch = 0; ch < 3; ++ch) {
          f[ch] = t.values[i + static_cast<std::size_t>(ch) * kMerlCells] * kMerlScale[ch];
          ok = ok && std::isfinite(f[ch]) && f[ch] >= 0;
        }
        if (!ok) continue;
        Eigen::Vector3d u, v;
        merl_cell_directions(a, b, c, &u, &v);
        if (u.z() < 0.05 || v.z() < 0.05) continue;
        out.push_back(make_fit_sample(u, v, f * u.z()));
      }
  if (out.empty()) throw bad_input("the MERL table has no measured cell above the horizon");
  return out;
}

}  // namespace fest::brdffit
