#pragma once
// Latitude-longitude (equirectangular) HDR environment maps, as Blender's studio lights
// ship them, with z up: row 0 looks straight up, the azimuth phi = atan2(y, -x) runs
// from the left edge (phi = -pi) to the right (phi = +pi) -- Blender's world mapping.
// Used as the background a camera sees behind an object and, through its irradiance
// (9 spherical-harmonic coefficients, Ramamoorthi & Hanrahan 2001), as diffuse ambient
// light on the object.

#include <array>
#include <vector>

#include <Eigen/Core>

namespace fest::reflectance {

struct EnvironmentMap {
  int width = 0, height = 0;
  std::vector<float> rgb;  // row-major, 3 floats per pixel, linear radiance

  // Radiance arriving from world direction `dir` (unit), bilinearly interpolated.
  Eigen::Vector3d radiance(const Eigen::Vector3d& dir) const;
};

// Irradiance E(n) = integral of L(w) max(0, n.w) dw, to second order in spherical harmonics.
struct IrradianceSH {
  std::array<Eigen::Vector3d, 9> coeff{};  // L_lm per RGB, (l, m) = (0,0), (1,-1), (1,0), (1,1), (2,-2) ... (2,2)
  Eigen::Vector3d irradiance(const Eigen::Vector3d& n) const;
};

IrradianceSH project_irradiance(const EnvironmentMap& env);

}  // namespace fest::reflectance
