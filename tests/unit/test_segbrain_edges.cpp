// Second-order edges against analytic cases (docs/segbrain.md §3): the moments of the Gaussian
// derivative kernels, the LoG zero crossing of a blurred step at the step's position
// (isotropic and anisotropic voxels), the zero crossings of a bright ball at its radius,
// and the in-plane scope that ignores changes along S.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "segbrain/derivatives.hpp"
#include "segbrain/edges.hpp"

#include "test_segbrain_helpers.hpp"

using namespace fest::segbrain;

namespace {

using fest::segbrain::test_support::grid;

// A step of height 100 at x = x0_mm along R, blurred by a Gaussian of s0 mm (the
// analytic erf profile), constant along A and S.
Image blurred_step(const Grid& g, double x0_mm, double s0) {
  Image img(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double x = double(i % g.n[0]) * g.spacing[0];
    img[i] = static_cast<float>(50 * (1 + std::erf((x - x0_mm) / (s0 * std::sqrt(2.0)))));
  }
  return img;
}

}  // namespace

TEST(SegbrainEdges, DerivativeKernelsHaveExactMoments) {
  for (double s : {0.7, 1.5, 2.0, 3.3}) {
    auto k0 = gaussian_derivative_kernel(s, 0), k1 = gaussian_derivative_kernel(s, 1), k2 = gaussian_derivative_kernel(s, 2);
    const int r = int(k0.size() / 2);
    double s0 = 0, s1 = 0, m1 = 0, s2 = 0, m2 = 0;
    for (int i = -r; i <= r; ++i) {
      s0 += k0[i + r];
      s1 += k1[i + r];
      m1 += i * k1[i + r];
      s2 += k2[i + r];
      m2 += double(i) * i * k2[i + r];
    }
    EXPECT_NEAR(s0, 1, 1e-12);
    EXPECT_NEAR(s1, 0, 1e-12);
    EXPECT_NEAR(m1, -1, 1e-12);  // convolution of the ramp x gives 1
    EXPECT_NEAR(s2, 0, 1e-12);
    EXPECT_NEAR(m2, 2, 1e-12);   // convolution of x^2 gives 2
  }
}

TEST(SegbrainEdges, SecondDerivativeOfAParabolaIsExact) {
  Grid g = grid(40, 3, 3, 0.5, 1, 1);
  Image img(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double x = double(i % g.n[0]) * 0.5;
    img[i] = static_cast<float>(3 * x * x);
  }
  Image log = laplacian_of_gaussian(g, img, 1.5, false);
  // Away from the replicated border (3 sigma = 9 voxels) the LoG is d²/dx² = 6 per mm².
  for (std::size_t x = 10; x < 30; ++x) EXPECT_NEAR(log[g.index(x, 1, 1)], 6.0, 1e-3);
}

TEST(SegbrainEdges, ZeroCrossingOfABlurredStepLiesAtTheStep) {
  // The LoG of an erf step is the derivative of a Gaussian centred on the step: its zero
  // lies at x0 whatever sigma. Linear interpolation between the two voxels of the sign
  // change recovers x0; the marked edge voxel is the one nearer to it.
  for (double spacing : {1.0, 0.5}) {
    for (double x0 : {20.3, 24.75, 22.5}) {
      Grid g = grid(std::size_t(48 / spacing), 4, 4, spacing, 1, 1);
      Image img = blurred_step(g, x0, 1.0);
      for (double sigma : {1.5, 2.0, 3.0}) {
        Image log = laplacian_of_gaussian(g, img, sigma, false);
        Mask edges = zero_crossings(g, log, 0.02, false);
        // Sign changes with a jump of at least 2 % of the peak (the operator's slope):
        // far from the step the LoG is zero up to rounding, whose signs are noise.
        double peak = 0;
        for (float v : log) peak = std::max(peak, double(std::abs(v)));
        int crossings = 0;
        for (std::size_t x = 0; x + 1 < g.n[0]; ++x) {
          const double a = log[g.index(x, 2, 2)], b = log[g.index(x + 1, 2, 2)];
          if (a * b >= 0 || std::abs(a - b) < 0.02 * peak) continue;
          ++crossings;
          const double at = (double(x) + a / (a - b)) * spacing;
          EXPECT_NEAR(at, x0, 0.05 * spacing) << "spacing " << spacing << " sigma " << sigma;
        }
        EXPECT_EQ(crossings, 1);
        std::size_t marked = 0, where = 0;
        for (std::size_t x = 0; x < g.n[0]; ++x)
          if (edges[g.index(x, 2, 2)]) ++marked, where = x;
        EXPECT_EQ(marked, 1u);
        EXPECT_LE(std::abs(double(where) * spacing - x0), 0.5 * spacing + 1e-9) << "spacing " << spacing << " x0 " << x0;
      }
    }
  }
}

TEST(SegbrainEdges, SlopeRejectsWeakCrossings) {
  Grid g = grid(48, 4, 4);
  Image img = blurred_step(g, 24.3, 1.0);
  // A faint ripple of 0.1 % of the step adds sign changes whose jumps stay under 10 % of
  // the step's peak response (but not under 5 %: one sits on the step's tail).
  for (std::size_t i = 0; i < g.size(); ++i) img[i] += static_cast<float>(0.1 * std::sin(double(i % 48) * 2.1));
  Image log = laplacian_of_gaussian(g, img, 0.7, false);
  auto count_row = [&](const Mask& m) {
    std::size_t n = 0;
    for (std::size_t x = 0; x < 48; ++x) n += m[g.index(x, 2, 2)];
    return n;
  };
  EXPECT_GT(count_row(zero_crossings(g, log, 0.0, false)), 1u);
  EXPECT_EQ(count_row(zero_crossings(g, log, 0.10, false)), 1u);
}

TEST(SegbrainEdges, ZeroCrossingsOfABallLieAtItsRadius) {
  // Bright ball, r = 20 mm, sigma 2 mm (docs/segbrain.md §3): every edge voxel within half a voxel
  // (plus the half voxel an axis-wise crossing may sit off the radial line) of r, and
  // the interpolated crossing on the axes through the centre within 0.5 voxel of r.
  Grid g = grid(56, 56, 56);
  const double c = 27.5, r = 20;
  Image img(g.size());
  for (std::size_t z = 0; z < 56; ++z)
    for (std::size_t y = 0; y < 56; ++y)
      for (std::size_t x = 0; x < 56; ++x) {
        const double d = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
        img[g.index(x, y, z)] = d <= r ? 100.0f : 0.0f;
      }
  Image log = laplacian_of_gaussian(g, img, 2.0, false);
  Mask edges = zero_crossings(g, log, 0.02, false);
  std::size_t n = 0;
  for (std::size_t z = 0; z < 56; ++z)
    for (std::size_t y = 0; y < 56; ++y)
      for (std::size_t x = 0; x < 56; ++x)
        if (edges[g.index(x, y, z)]) {
          ++n;
          const double d = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
          EXPECT_NEAR(d, r, 1.0) << x << "," << y << "," << z;
        }
  EXPECT_GT(n, 4000u);  // the sphere's area is 5027 mm²
  // Along +x through the centre row (y = z = 27, 28 straddle the centre symmetrically).
  double peak = 0;
  for (float v : log) peak = std::max(peak, double(std::abs(v)));
  const std::size_t y = 28, z = 28;
  bool found = false;
  for (std::size_t x = 30; x + 1 < 56; ++x) {
    const double a = log[g.index(x, y, z)], b = log[g.index(x + 1, y, z)];
    if (a * b < 0 && std::abs(a - b) >= 0.02 * peak) {
      found = true;
      const double at = double(x) + a / (a - b);
      const double radial = std::sqrt((at - c) * (at - c) + 2 * 0.25);
      EXPECT_NEAR(radial, r, 0.5);
      break;
    }
  }
  EXPECT_TRUE(found);
}

TEST(SegbrainEdges, InPlaneScopeIgnoresChangesAlongS) {
  Grid g = grid(8, 8, 40);
  Image img(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) img[i] = (i / 64) < 20 ? 0.0f : 100.0f;  // a step along S
  std::size_t in_plane = 0, volume = 0;
  for (auto v : marr_hildreth(g, img, 1.5, 0.02, true)) in_plane += v;
  for (auto v : marr_hildreth(g, img, 1.5, 0.02, false)) volume += v;
  EXPECT_EQ(in_plane, 0u);
  EXPECT_EQ(volume, 64u);  // one voxel per column
}

TEST(SegbrainEdges, FirstDerivativesOfARampAlongEachAxis) {
  // f = 2 R + 3 A - S (mm) on anisotropic voxels: every axis gives its slope per mm, with
  // the same sign convention (the Hessian's mixed terms rely on it).
  Grid g = grid(24, 20, 16, 0.8, 1.0, 1.5);
  Image img(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double x = double(i % 24) * 0.8, y = double((i / 24) % 20), z = double(i / 480) * 1.5;
    img[i] = static_cast<float>(2 * x + 3 * y - z);
  }
  const bool none[3] = {false, false, false};
  const int ox[3] = {1, 0, 0}, oy[3] = {0, 1, 0}, oz[3] = {0, 0, 1}, oxy[3] = {1, 1, 0};
  Image dx = gaussian_derivative(g, img, 1.0, ox, none), dy = gaussian_derivative(g, img, 1.0, oy, none);
  Image dz = gaussian_derivative(g, img, 1.0, oz, none), dxy = gaussian_derivative(g, img, 1.0, oxy, none);
  const std::size_t c = g.index(12, 10, 8);
  EXPECT_NEAR(dx[c], 2.0, 1e-4);
  EXPECT_NEAR(dy[c], 3.0, 1e-4);
  EXPECT_NEAR(dz[c], -1.0, 1e-4);
  EXPECT_NEAR(dxy[c], 0.0, 1e-4);
}
