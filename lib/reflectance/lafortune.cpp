#include "reflectance/lafortune.hpp"

#include <cmath>

namespace fest::reflectance {

Rgb evaluate(const LafortuneBrdf& brdf, const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  Rgb f = brdf.rho_d / M_PI;
  const double xy = u.x() * v.x() + u.y() * v.y(), z = u.z() * v.z();
  for (const LafortuneLobe& lobe : brdf.lobes)
    for (int c = 0; c < 3; ++c) {
      const double base = lobe.cxy[c] * xy + lobe.cz[c] * z;
      if (base > 0) f[c] += std::pow(base, lobe.n[c]);
    }
  return f;
}

Eigen::Matrix3d local_frame(const Eigen::Vector3d& n) {
  Eigen::Index least = 0;
  n.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d a = Eigen::Vector3d::Unit(least);
  const Eigen::Vector3d t = n.cross(a).normalized();
  Eigen::Matrix3d frame;
  frame.col(0) = t;
  frame.col(1) = n.cross(t);
  frame.col(2) = n;
  return frame;
}

LafortuneBrdf clay() {
  LafortuneBrdf b;
  b.rho_d = Rgb(0.383626, 0.260749, 0.274207);
  b.lobes = {
      {Rgb(-1.089701, -1.102701, -1.107603), Rgb(-1.354682, -2.714801, -1.569866),
       Rgb(17.968505, 11.024489, 21.270282)},
      {Rgb(-0.733381, -0.793320, -0.848206), Rgb(0.676108, 0.679314, 0.726031),
       Rgb(8.219745, 9.055139, 11.261951)},
      {Rgb(-1.010548, -1.012378, -1.011263), Rgb(0.910783, 0.885239, 0.892451),
       Rgb(152.912795, 141.937171, 201.046802)},
  };
  return b;
}

}  // namespace fest::reflectance
