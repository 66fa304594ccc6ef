// Separable BRDF approximation (docs/brdffit.md §6, `factor`): a Lambertian BRDF is
// exactly rank 1 in any parameterisation; a Lafortune lobe is more separable in half /
// difference angles than in (omega_o, omega_i).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "brdffit/separable.hpp"
#include "expect_error.hpp"

using namespace fest::brdffit;
using fest::reflectance::LafortuneBrdf;

namespace {

SeparableOptions small_grid() {
  SeparableOptions o;
  o.theta_bins = 8;
  o.phi_bins = 16;
  o.threads = 2;
  return o;
}

}  // namespace

TEST(BrdffitSeparable, HalfDifferenceMapsBackToMirrorPairs) {
  const Eigen::Vector3d half = Eigen::Vector3d(0.3, -0.2, 0.9).normalized();
  const Eigen::Vector3d diff = Eigen::Vector3d(0.4, 0.1, 0.8).normalized();
  Eigen::Vector3d in, out;
  half_difference_to_in_out(half, diff, in, out);
  EXPECT_NEAR(in.norm(), 1, 1e-12);
  EXPECT_NEAR(out.norm(), 1, 1e-12);
  EXPECT_LT(((in + out).normalized() - half).norm(), 1e-12);  // h is the half vector
  EXPECT_NEAR(in.dot(half), diff.z(), 1e-12);                 // theta_d is the angle of in to h
  // The pole: h = n leaves d unrotated.
  half_difference_to_in_out(Eigen::Vector3d::UnitZ(), diff, in, out);
  EXPECT_LT((in - diff).norm(), 1e-12);
  EXPECT_LT((out - Eigen::Vector3d(-diff.x(), -diff.y(), diff.z())).norm(), 1e-12);
}

TEST(BrdffitSeparable, LambertianIsExactlyRankOne) {
  LafortuneBrdf b;
  b.rho_d = {0.5, 0.3, 0.1};
  for (SeparableGrid grid : {SeparableGrid::half_difference, SeparableGrid::out_in}) {
    const SeparableFactors f = factor_brdf(b, grid, small_grid());
    EXPECT_LT(f.relative_rms_all, 1e-6);
    // g h^T reproduces rho / pi wherever both directions are above the surface.
    const std::size_t m = f.g.size();
    ASSERT_EQ(m, 8u * 16u);
    EXPECT_NEAR(f.g[0][0] * f.h[m - 1][0], 0.5 / M_PI, 1e-6);
    EXPECT_NEAR(f.g[m / 2][2] * f.h[3][2], 0.1 / M_PI, 1e-6);
  }
}

TEST(BrdffitSeparable, LafortuneLobeIsMoreSeparableInHalfDifferenceAngles) {
  LafortuneBrdf b;
  b.rho_d = {0.1, 0.1, 0.1};
  b.lobes.push_back({{-1, -1, -1}, {1, 1, 1}, {20, 20, 20}});
  const SeparableOptions o = small_grid();
  const SeparableFactors hd = factor_brdf(b, SeparableGrid::half_difference, o);
  const SeparableFactors oi = factor_brdf(b, SeparableGrid::out_in, o);
  std::printf("rank-1 relative RMS, Lafortune N = 20: half/difference %.4f, (omega_o, omega_i) %.4f\n",
              hd.relative_rms_all, oi.relative_rms_all);
  EXPECT_LT(hd.relative_rms_all, oi.relative_rms_all);
  EXPECT_GT(oi.relative_rms_all, 0.05);  // a real lobe is not rank 1 in (omega_o, omega_i)
}

TEST(BrdffitSeparable, BadGrid) {
  SeparableOptions o;
  o.theta_bins = 0;
  fest::test::expect_bad_input([&] { factor_brdf(LafortuneBrdf{}, SeparableGrid::out_in, o); }, "grid");
  o.theta_bins = 128;
  o.phi_bins = 128;
  fest::test::expect_bad_input([&] { factor_brdf(LafortuneBrdf{}, SeparableGrid::out_in, o); }, "4096");
}
