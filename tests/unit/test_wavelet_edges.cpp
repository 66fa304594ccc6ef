// Multiscale edges of analytic volumes: every edge point lies within half a voxel of
// the surface the mathematics puts it on, and the surface is found all round.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <cstdio>
#include <random>

#include "wavelet/edges.hpp"

using namespace fest;
using namespace fest::wavelet;

namespace {

Volume make(std::size_t n, const std::function<double(double, double, double)>& f) {
  Volume v;
  v.resize(n, n, n);
  for (std::size_t z = 0; z < n; ++z)
    for (std::size_t y = 0; y < n; ++y)
      for (std::size_t x = 0; x < n; ++x) v.at(x, y, z) = f(static_cast<double>(x), static_cast<double>(y), static_cast<double>(z));
  return v;
}

}  // namespace

TEST(WaveletEdges, SphereEdgesLieOnTheSphere) {
  const double cx = 20.3, cy = 19.6, cz = 20.9, r = 11.2;
  const Volume v = make(40, [&](double x, double y, double z) {
    const double d = std::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz));
    return 100.0 * std::clamp(r - d + 0.5, 0.0, 1.0);
  });
  const EdgeMap e = multiscale_edges(v, {});
  ASSERT_GT(e.points.size(), 500u);  // 4 pi r^2 ~ 1576 voxels of surface
  double worst = 0;
  for (const auto& p : e.points) {
    const double d = std::sqrt(std::pow(p.position[0] - cx, 2) + std::pow(p.position[1] - cy, 2) + std::pow(p.position[2] - cz, 2));
    worst = std::max(worst, std::fabs(d - r));
  }
  EXPECT_LE(worst, 0.5);
  // A step edge has Lipschitz regularity 0.
  double mean_alpha = 0;
  for (const auto& p : e.points) mean_alpha += p.alpha;
  EXPECT_NEAR(mean_alpha / static_cast<double>(e.points.size()), 0.0, 0.3);
}

TEST(WaveletEdges, PlaneStepIsFoundHalfwayBetweenVoxels) {
  const Volume v = make(24, [](double x, double, double) { return x <= 10 ? 0.0 : 50.0; });
  const EdgeMap e = multiscale_edges(v, {});
  ASSERT_EQ(e.points.size(), 24u * 24u);
  for (const auto& p : e.points) EXPECT_NEAR(p.position[0], 10.5, 1e-6);
}

TEST(WaveletEdges, BlurredCylinderEdgeAtItsRadius) {
  const double cx = 15.5, cy = 16.25, r = 7.6, s = 1.2;
  const Volume v = make(32, [&](double x, double y, double) {
    const double d = std::hypot(x - cx, y - cy);
    return 100.0 * 0.5 * std::erfc((d - r) / (s * std::sqrt(2.0)));
  });
  const EdgeMap e = multiscale_edges(v, {});
  ASSERT_GT(e.points.size(), 32u * 30u);  // 2 pi r ~ 48 voxels around, 32 slices
  for (const auto& p : e.points) EXPECT_NEAR(std::hypot(p.position[0] - cx, p.position[1] - cy), r, 0.5);
}

TEST(WaveletEdges, NoiseMaximaDoNotChainAcrossScales) {
  // A step of 40 in noise of sigma 4: the finest scale has maxima everywhere in the
  // noise, but only those on the step survive the chains (noise has alpha < 0: its
  // modulus decays across scales, Mallat & Zhong section IV).
  std::mt19937_64 rng(2);
  std::normal_distribution<double> g(0.0, 4.0);
  const Volume v = make(24, [&](double x, double, double) { return (x <= 10 ? 0.0 : 40.0) + g(rng); });
  EdgeOptions o;
  o.threshold = 0.5;
  const EdgeMap e = multiscale_edges(v, o);
  std::size_t on = 0, off = 0;
  for (const auto& p : e.points) (std::fabs(p.position[0] - 10.5) <= 1.0 ? on : off) += 1;
  std::printf("finest maxima %zu, kept on the step %zu, kept elsewhere %zu\n", e.maxima_per_scale[0], on, off);
  EXPECT_GT(e.maxima_per_scale[0], 2 * on);  // noise maxima at the finest scale
  EXPECT_GE(on, 24u * 24u * 9 / 10);
  EXPECT_LT(off, on / 2);
}
