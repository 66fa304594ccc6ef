#pragma once
// Small scenes for the radiosity tests.

#include "radiosity/scene.hpp"

namespace fest::radiosity::test {

// Unit cube [0,1]^3 as one object per face, faces facing inwards.
inline Scene furnace(double rho, double emission) {
  Scene s;
  using V = Eigen::Vector3d;
  const V c[8] = {V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 1), V(1, 1, 1), V(0, 1, 1)};
  // Counter-clockwise seen from inside.
  const int f[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}};
  for (int k = 0; k < 6; ++k) {
    SceneObject o;
    o.name = "face" + std::to_string(k);
    o.reflectance = Rgb::Constant(rho);
    o.emission = Rgb::Constant(emission);
    for (int j = 0; j < 4; ++j) o.vertices.push_back(c[f[k][j]]);
    o.faces.push_back({0, 1, 2, 3});
    s.objects.push_back(o);
  }
  return s;
}

inline Polygon square(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                      const Eigen::Vector3d& d) {
  Polygon p;
  p.n = 4;
  p.p = {a, b, c, d};
  return p;
}

}  // namespace fest::radiosity::test
