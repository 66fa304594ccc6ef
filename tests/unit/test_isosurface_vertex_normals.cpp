// Vertex normals (docs/isosurf.md "Vertex normals"): -grad f mapped to world space by A^-T.
#include <gtest/gtest.h>

#include <cmath>

#include "isosurface/marching_cubes.hpp"
#include "isosurface/vertex_normals.hpp"

using namespace fest::isosurface;
using fest::volume_pyramid::ScalarGrid;

// A sphere in index space with spacing (1, 1, 2) is the ellipsoid
// (x - c)^2 + (y - c)^2 + (z/2 - c)^2 = R^2 in world space; its outward normal is along
// (x - c, y - c, (z/2 - c)/2). Index-space normals (no A^-T) would be off by up to 18.4 degrees.
TEST(VertexNormals, AnisotropicSpacingUsesTheInverseTranspose) {
  const std::size_t n = 28;
  const double c = 13.5, R = 10;
  ScalarGrid g;
  g.dims = {n, n, n};
  g.axes = {1, 0, 0, 0, 1, 0, 0, 0, 2};
  g.values.resize(g.size());
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i)
        g.values[g.index(i, j, k)] = static_cast<float>(R - std::sqrt((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c)));
  Surface s = extract_isosurface(g, 0.0f, {}, nullptr);
  ASSERT_GT(s.vertices(), 100u);
  add_gradient_normals(g, s, 2);
  ASSERT_EQ(s.normals.size(), s.xyz.size());
  double worst = 0;
  for (std::size_t v = 0; v < s.vertices(); ++v) {
    const double e[3] = {s.xyz[3 * v] - c, s.xyz[3 * v + 1] - c, (s.xyz[3 * v + 2] / 2 - c) / 2};
    const double el = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    const float* m = &s.normals[3 * v];
    EXPECT_NEAR(std::sqrt(double(m[0]) * m[0] + double(m[1]) * m[1] + double(m[2]) * m[2]), 1.0, 1e-6);
    const double cosang = (e[0] * m[0] + e[1] * m[1] + e[2] * m[2]) / el;
    worst = std::max(worst, std::acos(std::min(1.0, cosang)) * 180 / M_PI);
  }
  EXPECT_LT(worst, 1.0);  // O((h/R)^2) rad = 0.57 degree, plus float storage
}
