// Lattice tables and the collision's conservation laws (docs/lbmsim.md 2.1-2.3).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lbm/collide.hpp"
#include "lbm/lattice.hpp"

namespace fest::lbm {
namespace {

template <class L>
void check_isotropy() {
  double s0 = 0, s1[3] = {0, 0, 0}, s2[3][3] = {}, s4[3][3][3][3] = {};
  for (int i = 0; i < L::Q; ++i) {
    s0 += L::w[i];
    for (int a = 0; a < 3; ++a) {
      s1[a] += L::w[i] * L::c[i][a];
      for (int b = 0; b < 3; ++b) {
        s2[a][b] += L::w[i] * L::c[i][a] * L::c[i][b];
        for (int g = 0; g < 3; ++g)
          for (int d = 0; d < 3; ++d) s4[a][b][g][d] += L::w[i] * L::c[i][a] * L::c[i][b] * L::c[i][g] * L::c[i][d];
      }
    }
    for (int a = 0; a < 3; ++a) EXPECT_EQ(L::c[L::opp[i]][a], -L::c[i][a]) << i;
    EXPECT_EQ(L::w[L::opp[i]], L::w[i]);
  }
  EXPECT_NEAR(s0, 1.0, 1e-15);
  for (int a = 0; a < L::D; ++a) {
    EXPECT_NEAR(s1[a], 0.0, 1e-15);
    for (int b = 0; b < L::D; ++b) {
      EXPECT_NEAR(s2[a][b], a == b ? 1.0 / 3 : 0.0, 1e-15);
      for (int g = 0; g < L::D; ++g)
        for (int d = 0; d < L::D; ++d) {
          const double k = ((a == b) * (g == d) + (a == g) * (b == d) + (a == d) * (b == g)) / 9.0;
          EXPECT_NEAR(s4[a][b][g][d], k, 1e-15) << a << b << g << d;
        }
    }
  }
}

TEST(LbmLattice, D2Q9TablesAreIsotropicToFourthOrder) { check_isotropy<D2Q9>(); }
TEST(LbmLattice, D3Q19TablesAreIsotropicToFourthOrder) { check_isotropy<D3Q19>(); }

TEST(LbmLattice, SpecOrderingIsFixed) {
  EXPECT_EQ(D2Q9::c[5][0], 1);
  EXPECT_EQ(D2Q9::c[5][1], 1);
  EXPECT_EQ(D2Q9::opp[5], 7);
  EXPECT_EQ(D3Q19::c[14][0], -1);
  EXPECT_EQ(D3Q19::c[14][2], 1);
  for (int i = 1; i < 19; ++i) EXPECT_EQ(D3Q19::opp[i], i % 2 ? i + 1 : i - 1);
}

// compressible = 0: He & Luo's (1997) incompressible form, whose momentum terms carry
// rho0 = 1: sum f = rho, sum f c = u, sum f c c = rho/3 I + u u.
template <class L>
void check_equilibrium_moments(double compressible = 1) {
  const double drho = 0.03, u[3] = {0.04, -0.02, L::D == 3 ? 0.015 : 0.0};
  double m0 = 0, m1[3] = {0, 0, 0}, m2[3][3] = {};
  for (int i = 0; i < L::Q; ++i) {
    const double f = equilibrium<L, double>(i, drho, u, compressible) + L::w[i];
    m0 += f;
    for (int a = 0; a < 3; ++a) {
      m1[a] += f * L::c[i][a];
      for (int b = 0; b < 3; ++b) m2[a][b] += f * L::c[i][a] * L::c[i][b];
    }
  }
  const double rho = 1 + drho, rho_m = 1 + compressible * drho;
  EXPECT_NEAR(m0, rho, 1e-14);
  for (int a = 0; a < L::D; ++a) {
    EXPECT_NEAR(m1[a], rho_m * u[a], 1e-14);
    for (int b = 0; b < L::D; ++b) EXPECT_NEAR(m2[a][b], rho / 3 * (a == b) + rho_m * u[a] * u[b], 1e-14);
  }
}

TEST(LbmCollide, EquilibriumMomentsD2Q9) { check_equilibrium_moments<D2Q9>(); }
TEST(LbmCollide, EquilibriumMomentsD3Q19) { check_equilibrium_moments<D3Q19>(); }
TEST(LbmCollide, IncompressibleEquilibriumMoments) {
  check_equilibrium_moments<D2Q9>(0);
  check_equilibrium_moments<D3Q19>(0);
}

template <class L, bool TRT>
void check_conservation() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-0.01, 0.01);
  CollideParams<double> p;
  p.omega_p = 1 / 0.7;
  p.omega_m = TRT ? 1 / (0.5 + 0.1875 / 0.2) : p.omega_p;
  p.force[0] = 1e-4;
  p.force[1] = -2e-4;
  p.force[2] = L::D == 3 ? 3e-4 : 0;
  for (int trial = 0; trial < 50; ++trial) {
    double f[L::Q], o[L::Q];
    for (int i = 0; i < L::Q; ++i) f[i] = d(rng) * L::w[i];
    collide<L, double, TRT, true>(f, o, p);
    double m0 = 0, m0o = 0, j[3] = {0, 0, 0}, jo[3] = {0, 0, 0};
    for (int i = 0; i < L::Q; ++i) {
      m0 += f[i];
      m0o += o[i];
      for (int a = 0; a < 3; ++a) j[a] += L::c[i][a] * f[i], jo[a] += L::c[i][a] * o[i];
    }
    EXPECT_NEAR(m0o, m0, 1e-15);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(jo[a], j[a] + p.force[a], 1e-15);  // the collision adds F
  }
}

TEST(LbmCollide, BgkConservesMassAndMomentumPlusForce) {
  check_conservation<D2Q9, false>();
  check_conservation<D3Q19, false>();
}
TEST(LbmCollide, TrtConservesMassAndMomentumPlusForce) {
  check_conservation<D2Q9, true>();
  check_conservation<D3Q19, true>();
}

TEST(LbmCollide, TrtWithEqualRatesIsBgk) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-0.01, 0.01);
  CollideParams<double> p;
  p.omega_p = p.omega_m = 1 / 0.8;
  double f[19], a[19], b[19];
  for (double& v : f) v = d(rng);
  collide<D3Q19, double, true, false>(f, a, p);
  collide<D3Q19, double, false, false>(f, b, p);
  for (int i = 0; i < 19; ++i) EXPECT_NEAR(a[i], b[i], 1e-17);
}

}  // namespace
}  // namespace fest::lbm
