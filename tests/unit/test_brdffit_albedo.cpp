#include "brdffit/lobe_albedo.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "brdffit/lafortune_fit.hpp"
#include "brdffit/lafortune_model.hpp"
#include "brdffit_test_data.hpp"
#include "reflectance/lafortune.hpp"

using namespace fest::brdffit;

namespace {

// Brute force: a(u) = sum over a fine (theta_v, phi_v) grid of the lobe times v_z, for
// incident polar angles on a grid; valid for broad lobes only (small N).
double brute_force_max_albedo(double cxy, double cz, double n) {
  const int nt = 150, np = 300, nu = 46;
  double best = 0;
  for (int k = 0; k < nu; ++k) {
    const double tu = M_PI / 2 * k / (nu - 1);
    const double ux = std::sin(tu), uz = std::cos(tu);
    double sum = 0;
    for (int i = 0; i < nt; ++i) {
      const double tv = M_PI / 2 * (i + 0.5) / nt;
      for (int j = 0; j < np; ++j) {
        const double pv = 2 * M_PI * (j + 0.5) / np;
        const double vx = std::sin(tv) * std::cos(pv), vz = std::cos(tv);
        const double base = cxy * ux * vx + cz * uz * vz;
        if (base > 0) sum += std::pow(base, n) * vz * std::sin(tv);
      }
    }
    best = std::max(best, sum * (M_PI / 2 / nt) * (2 * M_PI / np));
  }
  return best;
}

}  // namespace

TEST(BrdffitAlbedo, MirrorLobeAtNormalIncidenceHasTheClosedForm) {
  // Cxy = -Cz = -1: the lobe is (v . mirror(u))^N; its albedo is largest at normal
  // incidence, where integral cos^N(theta) cos(theta) dw = 2 pi / (N + 2).
  for (double n : {1.0, 5.0, 60.0, 1e3, 1e4}) {
    const double expected = 2 * M_PI / (n + 2);
    EXPECT_NEAR(std::exp(lobe_log_max_albedo(-1, 1, n)), expected, 2e-3 * expected) << "N = " << n;
    // Homogeneous of degree N in (Cxy, Cz): log a grows by N log s.
    EXPECT_NEAR(lobe_log_max_albedo(-1.5, 1.5, n), std::log(expected) + n * std::log(1.5), 2e-3 * (1 + n)) << n;
  }
}

TEST(BrdffitAlbedo, AgreesWithBruteForceOnOffSpecularAndRetroLobes) {
  struct Case {
    double cxy, cz, n;
  };
  for (const Case c : {Case{-1.5, 0.6, 3}, Case{0.9, 1.1, 4}, Case{-1.1, -1.35, 6}, Case{-0.73, 0.68, 8.2}}) {
    const double expected = brute_force_max_albedo(c.cxy, c.cz, c.n);
    EXPECT_NEAR(std::exp(lobe_log_max_albedo(c.cxy, c.cz, c.n)), expected, 5e-3 * expected)
        << c.cxy << " " << c.cz << " " << c.n;
  }
  EXPECT_EQ(lobe_log_max_albedo(0, 0, 10), -std::numeric_limits<double>::infinity());
}

TEST(BrdffitAlbedo, BoundScalesDownTheRunawayLobeAndKeepsPlausibleOnes) {
  // The runaway fit of issue 12: Cz = 1.31, N = 10^4 is zero at every sample of a
  // broad material but 1.31^10000 at light = view = normal.
  const ModelSpec spec;
  Eigen::VectorXd p(parameter_count(spec));
  for (int c = 0; c < 3; ++c) p.segment(4 * c, 4) << 0.1, 0.87, 1.31, std::log(1e4);
  clamp_to_bounds(spec, p);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(std::exp(lobe_log_max_albedo(p[4 * c + 1], p[4 * c + 2], std::exp(p[4 * c + 3]))), 1 + 1e-9);
    EXPECT_NEAR(p[4 * c + 2] / p[4 * c + 1], 1.31 / 0.87, 1e-12);  // the shape is kept
  }
  // Measured lobes are physically plausible: the clay's three lobes stay as they are.
  const ModelSpec clay_spec{3, false};
  const Eigen::VectorXd clay = from_brdf(clay_spec, fest::reflectance::clay());
  Eigen::VectorXd q = clay;
  clamp_to_bounds(clay_spec, q);
  EXPECT_EQ(q, clay);
  // The shared-lobe layout caps the per-channel scales instead.
  const ModelSpec shared{1, true};
  Eigen::VectorXd s(parameter_count(shared));
  s << 0.2, 0.3, 0.4, 50, 100, 2, -1.0, std::log(20.0);
  clamp_to_bounds(shared, s);
  const double unit = std::exp(lobe_log_max_albedo(-1.0, 1.0, 20));
  EXPECT_NEAR(s[4] * unit, 1, 1e-9);
  EXPECT_NEAR(s[3] * unit, 1, 1e-9);
  EXPECT_DOUBLE_EQ(s[5], 2);  // below the bound already
  // 0 switches the bound off.
  ModelSpec unbounded;
  unbounded.max_lobe_albedo = 0;
  Eigen::VectorXd r = p;
  r[2] = 1.31;
  clamp_to_bounds(unbounded, r);
  EXPECT_EQ(r[2], 1.31);
}

TEST(BrdffitAlbedo, BoundFollowsTheDataUnitsOnlyWhenUncalibrated) {
  // Calibrated radiance of a plausible material: median apparent albedo below 1, the
  // physical bound stays. The same radiance in camera units (x 1e6) scales the bound.
  fest::reflectance::LafortuneBrdf b;
  b.rho_d = fest::reflectance::Rgb::Constant(0.4);
  b.lobes = {fest::reflectance::LafortuneLobe{fest::reflectance::Rgb::Constant(-1.0),
                                              fest::reflectance::Rgb::Constant(1.0),
                                              fest::reflectance::Rgb::Constant(20)}};
  auto samples = brdffit_test::samples_of(b, 2000, 3);
  EXPECT_EQ(albedo_bound_in_data_units(1.0, samples), 1.0);
  EXPECT_EQ(albedo_bound_in_data_units(0.0, samples), 0.0);
  for (FitSample& s : samples)
    for (float& r : s.r) r *= 1e6f;
  const double scaled = albedo_bound_in_data_units(1.0, samples);
  EXPECT_GT(scaled, 0.4e6);  // at least the diffuse albedo's apparent value
  EXPECT_LT(scaled, 1e8);
}
