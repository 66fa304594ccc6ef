// Taubin lambda|mu smoothing (docs/isosurf.md "Smoothing").
#include <gtest/gtest.h>

#include <cmath>

#include "isosurface/marching_cubes.hpp"
#include "isosurface/taubin_smooth.hpp"

using namespace fest::isosurface;
using fest::volume_pyramid::ScalarGrid;

namespace {

Surface sphere(double R, double c, std::size_t n) {
  ScalarGrid g;
  g.dims = {n, n, n};
  g.values.resize(g.size());
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i)
        g.values[g.index(i, j, k)] = static_cast<float>(R - std::sqrt((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c)));
  return extract_isosurface(g, 0.0f, {}, nullptr);
}

void radius_stats(const Surface& s, double c, double& mean, double& rms_to, double R) {
  mean = 0, rms_to = 0;
  for (std::size_t v = 0; v < s.vertices(); ++v) {
    const double x = s.xyz[3 * v] - c, y = s.xyz[3 * v + 1] - c, z = s.xyz[3 * v + 2] - c;
    const double r = std::sqrt(x * x + y * y + z * z);
    mean += r, rms_to += (r - R) * (r - R);
  }
  mean /= double(s.vertices());
  rms_to = std::sqrt(rms_to / double(s.vertices()));
}

}  // namespace

// A noisy sphere: Taubin smoothing removes most of the noise (a low-pass filter) and keeps
// the radius, where as many plain Laplacian steps (mu = 0) shrink it (Taubin 1995, sec. 4).
TEST(TaubinSmooth, RemovesNoiseWithoutShrinking) {
  const double R = 12, c = 15.5;
  Surface s = sphere(R, c, 32);
  ASSERT_GT(s.vertices(), 500u);
  for (std::size_t v = 0; v < s.vertices(); ++v) {  // deterministic radial noise of +-0.3
    const double e = 0.3 * std::sin(double(v) * 12.9898) * (v % 2 ? 1 : -1);
    double p[3];
    for (int a = 0; a < 3; ++a) p[a] = s.xyz[3 * v + a] - c;
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int a = 0; a < 3; ++a) s.xyz[3 * v + a] = static_cast<float>(c + p[a] * (r + e) / r);
  }
  double mean0, rms0, mean1, rms1, mean2, rms2;
  radius_stats(s, c, mean0, rms0, R);
  Surface t = s, l = s;
  taubin_smooth(t, 10);
  taubin_smooth(l, 10, 0.5, 0.0);  // 10 lambda steps (and 10 no-op mu steps): plain Laplacian
  radius_stats(t, c, mean1, rms1, R);
  radius_stats(l, c, mean2, rms2, R);
  EXPECT_LT(rms1, rms0 / 2);
  EXPECT_NEAR(mean1, R, 0.01 * R);
  EXPECT_LT(mean2, mean1 - 0.05);  // the plain Laplacian shrinks more
}

// Boundary vertices stay where they are; an isolated triangle has only boundary edges.
TEST(TaubinSmooth, BoundaryIsFixed) {
  Surface s;
  s.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  s.triangles = {{0, 1, 2}};
  const auto before = s.xyz;
  taubin_smooth(s, 5);
  EXPECT_EQ(s.xyz, before);
}
