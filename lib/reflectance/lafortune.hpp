#pragma once
// The Lafortune BRDF (Lafortune, Foo, Torrance, Greenberg, SIGGRAPH 1997), isotropic, as
// docs/brdffit.md §2 uses it; shared by brdffit (fitting, rendering) and the simulated
// camera of capture (which renders objects made of known materials). Per colour channel c:
//
//   f_c(u, v) = rho_d,c / pi + sum_k max(0, Cxy_k,c (ux vx + uy vy) + Cz_k,c uz vz)^N_k,c
//
// with u (towards the light) and v (towards the viewer) unit vectors in the local frame
// (t, b, n) of the surface point. The max(0, .) clamp keeps non-integer exponents defined.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fest::reflectance {

using Rgb = Eigen::Vector3d;

struct LafortuneLobe {
  Rgb cxy = Rgb::Zero();  // Cx = Cy (isotropy); a mirror lobe has cxy = -cz < 0
  Rgb cz = Rgb::Zero();
  Rgb n = Rgb::Ones();    // exponent per channel
};

struct LafortuneBrdf {
  Rgb rho_d = Rgb::Zero();  // diffuse albedo; the diffuse term is rho_d / pi
  std::vector<LafortuneLobe> lobes;
};

// f_r(u, v) per channel; u, v in the local frame (z = normal). Directions below the
// surface are the caller's business (the radiance sample multiplies by u_z).
Rgb evaluate(const LafortuneBrdf& brdf, const Eigen::Vector3d& u_local, const Eigen::Vector3d& v_local);

// The local frame of docs/brdffit.md §1: t = normalize(n x a), a = the world axis least aligned with n,
// b = n x t. Columns of the result are t, b, n, so local = frame.transpose() * world.
Eigen::Matrix3d local_frame(const Eigen::Vector3d& unit_normal);

// pbrt-v1's "clay" (3 lobes, measured by Lafortune et al.), the reference material of docs/brdffit.md §7.
LafortuneBrdf clay();

}  // namespace fest::reflectance
