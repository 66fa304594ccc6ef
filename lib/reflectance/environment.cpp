#include "reflectance/environment.hpp"

#include <algorithm>
#include <cmath>

namespace fest::reflectance {
namespace {

// Real spherical harmonics up to l = 2 (the constants of Ramamoorthi & Hanrahan 2001).
std::array<double, 9> sh_basis(const Eigen::Vector3d& d) {
  const double x = d.x(), y = d.y(), z = d.z();
  return {0.282095,         0.488603 * y,       0.488603 * z,     0.488603 * x, 1.092548 * x * y,
          1.092548 * y * z, 0.315392 * (3 * z * z - 1), 1.092548 * x * z, 0.546274 * (x * x - y * y)};
}

Eigen::Vector3d pixel(const EnvironmentMap& env, int x, int y) {
  x = ((x % env.width) + env.width) % env.width;  // azimuth wraps around
  y = std::clamp(y, 0, env.height - 1);
  const float* p = &env.rgb[(static_cast<std::size_t>(y) * env.width + x) * 3];
  return {p[0], p[1], p[2]};
}

// Direction of the centre of pixel (x, y).
Eigen::Vector3d direction(const EnvironmentMap& env, double x, double y) {
  const double theta = (y + 0.5) / env.height * M_PI;
  const double phi = (x + 0.5) / env.width * 2 * M_PI - M_PI;
  const double s = std::sin(theta);
  return {-s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

}  // namespace

Eigen::Vector3d EnvironmentMap::radiance(const Eigen::Vector3d& dir) const {
  if (width <= 0 || height <= 0) return Eigen::Vector3d::Zero();
  const double theta = std::acos(std::clamp(dir.z(), -1.0, 1.0));
  const double phi = std::atan2(dir.y(), -dir.x());
  const double fx = (phi + M_PI) / (2 * M_PI) * width - 0.5;
  const double fy = theta / M_PI * height - 0.5;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double ax = fx - x0, ay = fy - y0;
  return (1 - ay) * ((1 - ax) * pixel(*this, x0, y0) + ax * pixel(*this, x0 + 1, y0)) +
         ay * ((1 - ax) * pixel(*this, x0, y0 + 1) + ax * pixel(*this, x0 + 1, y0 + 1));
}

IrradianceSH project_irradiance(const EnvironmentMap& env) {
  IrradianceSH sh;
  for (auto& c : sh.coeff) c.setZero();
  if (env.width <= 0 || env.height <= 0) return sh;
  const double dphi = 2 * M_PI / env.width, dtheta = M_PI / env.height;
  for (int y = 0; y < env.height; ++y) {
    const double theta = (y + 0.5) * dtheta;
    const double domega = std::sin(theta) * dphi * dtheta;
    for (int x = 0; x < env.width; ++x) {
      const std::array<double, 9> b = sh_basis(direction(env, x, y));
      const Eigen::Vector3d L = pixel(env, x, y);
      for (int k = 0; k < 9; ++k) sh.coeff[static_cast<std::size_t>(k)] += L * (b[static_cast<std::size_t>(k)] * domega);
    }
  }
  return sh;
}

Eigen::Vector3d IrradianceSH::irradiance(const Eigen::Vector3d& n) const {
  // Convolution with the clamped cosine: A0 = pi, A1 = 2 pi / 3, A2 = pi / 4.
  static const double a[9] = {M_PI, 2 * M_PI / 3, 2 * M_PI / 3, 2 * M_PI / 3, M_PI / 4,
                              M_PI / 4, M_PI / 4, M_PI / 4, M_PI / 4};
  const std::array<double, 9> b = sh_basis(n);
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  for (int k = 0; k < 9; ++k) e += coeff[static_cast<std::size_t>(k)] * (a[k] * b[static_cast<std::size_t>(k)]);
  return e.cwiseMax(0.0);
}

}  // namespace fest::reflectance
