// The inline closed-form kernels of the predicted exit (flow_kernels.hpp) and the record's
// speed bound: the Taylor polynomials against the math library in long double over their
// whole range (tier boundaries included), and the bound against the interpolated speed
// at random points of random cells. Expected values come from libm and from the
// definition of the interpolant, not from the code under test.

#include <climits>
#include <complex>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "lemtrace/cell_field.hpp"
#include "lemtrace/flow_kernels.hpp"

namespace {

using namespace fest::lemtrace;

// Arguments over [-lim, lim]: a uniform sweep, the tier boundaries of phi1_small and their
// neighbours, and tiny values.
std::vector<double> arguments(double lim) {
  std::vector<double> xs;
  for (int i = -2000; i <= 2000; ++i) xs.push_back(lim * i / 2000.0);
  for (double b : {0x1p-10, 0.0625, 0.25, 1e-300, 1e-17, 1e-9, 3e-6, 1e-3})
    for (double x : {b, std::nextafter(b, 0.0), std::nextafter(b, 1.0)})
      if (x <= lim) {
        xs.push_back(x);
        xs.push_back(-x);
      }
  return xs;
}

TEST(LemtraceFlowKernels, Phi1PolynomialMatchesExpm1) {
  // phi1(x) = (e^x - 1) / x; the reference in long double, phi1(0) = 1.
  double worst = 0;
  for (double x : arguments(0.25)) {
    const long double ref = x == 0 ? 1.0L : std::expm1(static_cast<long double>(x)) / x;
    const double rel = static_cast<double>(std::abs((phi1_small(x) - ref) / ref));
    worst = std::max(worst, rel);
    EXPECT_LE(rel, 5e-16) << "x = " << x;  // two ulps, and the reference's own rounding
  }
  EXPECT_GT(worst, 0.0);  // the comparison is not vacuous
  // Outside the polynomial's range phi1 is expm1(x) / x itself.
  for (double x : {0.2500001, -0.3, 1.0, -4.0, 20.0}) EXPECT_EQ(phi1(x), std::expm1(x) / x) << x;
}

TEST(LemtraceFlowKernels, ExpAndPsiMatchTheLibrary) {
  for (double l : {-3.0, -0.7, -1e-9, 0.0, 2e-12, 0.4, 2.5})
    for (double s : {-0.08, -1e-4, 0.0, 1e-7, 0.01, 0.0999}) {
      double e, p;
      exp_and_psi(l, s, e, p);
      const long double x = static_cast<long double>(l) * s;
      EXPECT_NEAR(e, static_cast<double>(std::exp(x)), 4e-16) << l << " " << s;
      const double p_ref = l == 0 ? s : static_cast<double>(std::expm1(x) / l);
      EXPECT_NEAR(p, p_ref, 4e-16 * std::abs(p_ref)) << l << " " << s;
    }
}

TEST(LemtraceFlowKernels, SmallSincosMatchesTheLibrary) {
  for (double t : arguments(0.5)) {
    double sn, cs;
    small_sincos(t, &sn, &cs);
    const long double lt = t;
    EXPECT_NEAR(sn, static_cast<double>(std::sin(lt)), 2.5e-16 * std::abs(t) + 1e-300) << t;
    EXPECT_NEAR(cs, static_cast<double>(std::cos(lt)), 2.5e-16) << t;
  }
  for (double t : {0.7, -2.0, 10.0}) {  // outside the series: the library
    double sn, cs;
    small_sincos(t, &sn, &cs);
    EXPECT_EQ(sn, std::sin(t));
    EXPECT_EQ(cs, std::cos(t));
  }
}

// The complex pair's block of the flow is the exponential of the 2x2 system
// z' = [[a, b], [-b, a]] z + c: checked against the variation-of-constants integral
// evaluated with the library's exp/sin/cos in long double.
TEST(LemtraceFlowKernels, ComplexPairFlowSolvesItsSystem) {
  for (double a : {-0.8, 0.0, 1e-7, 0.3})
    for (double b : {0.05, 1.0, 4.0})
      for (double s : {-0.05, 0.001, 0.04, 0.3}) {
        const double z0[2] = {0.3, -0.7}, c[2] = {0.2, 0.9};
        double z[2];
        complex_pair_flow(a, b, s, z0, c, z);
        // Complex form: zeta = z0 + i z1 solves zeta' = (a - i b) zeta + (c0 + i c1).
        using C = std::complex<long double>;
        // e - 1 from expm1 and the half angle, so that the reference does not cancel
        // either (long double may be no wider than double, e.g. under valgrind).
        const long double as = static_cast<long double>(a) * s, bs = static_cast<long double>(b) * s;
        const long double ea = std::exp(as), sh = std::sin(bs / 2);
        const C e(ea * std::cos(bs), -ea * std::sin(bs));
        const C em1(std::expm1(as) * std::cos(bs) - 2 * sh * sh, -ea * std::sin(bs));
        const C mu(a, -b), zeta0(z0[0], z0[1]), gamma(c[0], c[1]);
        const C zeta = e * zeta0 + em1 / mu * gamma;
        EXPECT_NEAR(z[0], static_cast<double>(zeta.real()), 1e-15) << a << " " << b << " " << s;
        EXPECT_NEAR(z[1], static_cast<double>(zeta.imag()), 1e-15) << a << " " << b << " " << s;
      }
}

// speed_log2 bounds |v| from below everywhere in the cell, and exists where the vertex
// vectors share a direction.
TEST(LemtraceFlowKernels, RecordSpeedBoundHoldsInsideTheCell) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  int bounded = 0, normal = 0;
  for (int trial = 0; trial < 400; ++trial) {
    TetMesh m;
    const Vec3 mean = trial % 4 == 0 ? Vec3(Vec3::Zero()) : Vec3(Vec3(1.0, 0.4, -0.2) * std::pow(10.0, 4 * u(rng)));
    const Vec3 base[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (const Vec3& p : base) {
      m.points.push_back(0.1 * (p + 0.2 * Vec3(u(rng), u(rng), u(rng))));
      m.vectors.push_back(mean + mean.norm() * 0.5 * Vec3(u(rng), u(rng), u(rng)) + 0.3 * Vec3(u(rng), u(rng), u(rng)));
    }
    m.tets.push_back({0, 1, 2, 3});
    if (signed_volume(m.points[0], m.points[1], m.points[2], m.points[3]) < 0) std::swap(m.tets[0][2], m.tets[0][3]);
    const TetGeometry g = tet_geometry(m, 0);
    const CellRecord world = classify(g, ClassifyParams{});
    if (world.type != CellType::normal_real && world.type != CellType::normal_complex) continue;
    ++normal;
    const CellRecord r = to_barycentric_frame(g, world);
    if (r.speed_log2 == INT8_MIN) continue;
    ++bounded;
    const double bound = std::ldexp(1.0, r.speed_log2);
    for (int i = 0; i < 200; ++i) {
      Eigen::Vector4d beta(w(rng), w(rng), w(rng), w(rng));
      if (i < 4) beta = Eigen::Vector4d::Unit(i);  // the vertices themselves
      beta /= beta.sum();
      EXPECT_GE(g.interpolate(beta).norm(), bound) << "trial " << trial;
    }
  }
  EXPECT_GT(normal, 200);
  EXPECT_GT(bounded, 100);
}

}  // namespace
