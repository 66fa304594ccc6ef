// The parallel projection (docs/fluidsim.md §4, tests 1-3): class sizes, class
// independence, exactness of every solver, the checkerboard null mode.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "fluidsim/operators.hpp"
#include "fluidsim/projection.hpp"

using namespace fest::fluidsim;

namespace {

Layout closed3(int n) {
  return Layout::make(3, {n, n, n}, {Boundary::closed, Boundary::closed, Boundary::closed}, 1.0 / (n + 1));
}

Velocity random_field(const Layout& L, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  Velocity u;
  for (int c = 0; c < 3; ++c) {
    u[c] = c < L.dim ? L.zeros() : Field();
    for (double& v : u[c]) v = U(rng);
  }
  return u;
}

}  // namespace

TEST(FluidsimProjection, ClassSizesAreTheSeedsSubgridSizes) {
  // floor(n/2)+1 and ceil(n/2)+1 along each closed axis (the seed's pois3d size rule).
  for (int n : {15, 16, 31}) {
    const Layout L = closed3(n);
    const Projector P(L, {});
    ASSERT_EQ(P.class_count(), 8);
    for (int c = 0; c < 8; ++c)
      for (int a = 0; a < 3; ++a) {
        const int m = P.class_size(c)[a];
        EXPECT_TRUE(m == n / 2 + 1 || m == (n + 1) / 2 + 1) << "n=" << n << " m=" << m;
      }
  }
  const Layout L2 = Layout::make(2, {20, 9, 1}, {Boundary::closed, Boundary::closed, Boundary::closed}, 0.1);
  EXPECT_EQ(Projector(L2, {}).class_count(), 4);
}

TEST(FluidsimProjection, ClassesAreIndependent) {
  // Perturbing the right-hand side on one parity class changes q there only: exact zero
  // elsewhere (the 8 problems share no unknowns).
  const Layout L = closed3(9);
  for (PoissonSolver s : {PoissonSolver::fdm, PoissonSolver::fft}) {
    ProjectionOptions po;
    po.solver = s;
    const Projector P(L, po);
    Field rhs = L.zeros(), q0, q1;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> U(-1, 1);
    for (double& v : rhs) v = U(rng);
    P.solve(rhs, q0);
    Field bumped = rhs;
    // Two opposite bumps in class (1,0,0) keep the class's right-hand side compatible.
    bumped[L.index(3, 2, 4)] += 1.0;
    bumped[L.index(5, 4, 6)] -= 1.0;
    P.solve(bumped, q1);
    for (int k = 0; k < L.size[2]; ++k)
      for (int j = 0; j < L.size[1]; ++j)
        for (int i = 0; i < L.size[0]; ++i) {
          const bool same_class = i % 2 == 1 && j % 2 == 0 && k % 2 == 0;
          if (!same_class) {
            EXPECT_EQ(q0[L.index(i, j, k)], q1[L.index(i, j, k)]) << i << "," << j << "," << k;
          }
        }
  }
}

TEST(FluidsimProjection, EverySolverIsExact) {
  for (int n : {10, 11}) {
    const Layout L = closed3(n);
    for (PoissonSolver s : {PoissonSolver::fdm, PoissonSolver::fft, PoissonSolver::mg}) {
      ProjectionOptions po;
      po.solver = s;
      po.tol = 1e-13;
      Velocity u = random_field(L, 1);
      const ProjectionStats st = Projector(L, po).project(u);
      EXPECT_LE(st.max_div_after, 1e-10 * st.max_div_before) << poisson_name(s) << " n=" << n;
    }
  }
}

TEST(FluidsimProjection, AnchorsLeaveResidualDivergence) {
  // 20 Gauss-Seidel sweeps with the compact Laplacian (Stam 2003) are not a projection.
  const Layout L = Layout::make(2, {64, 64, 1}, {Boundary::closed, Boundary::closed, Boundary::closed}, 1.0 / 65);
  ProjectionOptions po;
  po.solver = PoissonSolver::gs;
  po.compact = true;
  Velocity u = random_field(L, 2);
  const ProjectionStats st = Projector(L, po).project(u);
  EXPECT_GT(st.max_div_after, 1e-4 * st.max_div_before);
  EXPECT_LT(st.max_div_after, st.max_div_before);
}

TEST(FluidsimProjection, CheckerboardIsInTheNullSpaceOfCentralDivergence) {
  const Layout L = Layout::make(3, {16, 16, 16}, {Boundary::periodic, Boundary::periodic, Boundary::periodic}, 1.0 / 16);
  Velocity u;
  for (int c = 0; c < 3; ++c) {
    u[c] = L.zeros();
    for (int k = 0; k < 16; ++k)
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) u[c][L.index(i, j, k)] = (i + j + k) % 2 ? -1.0 : 1.0;
  }
  Field div;
  divergence(L, u, div);
  EXPECT_EQ(max_abs(div), 0.0);
  Velocity p = u;
  Projector(L, {}).project(p);
  for (int c = 0; c < 3; ++c)
    for (std::size_t n = 0; n < u[c].size(); ++n) EXPECT_NEAR(p[c][n], u[c][n], 1e-12);
}

TEST(FluidsimProjection, SizeRuleOfTheSeed) {
  // The seed: 31 (32 = 2^5) is fast, 30 (31 prime) slow; 63 (64) fast, 64 (65 = 5 x 13) slow.
  EXPECT_TRUE(fft_friendly(31));
  EXPECT_FALSE(fft_friendly(30));
  EXPECT_TRUE(fft_friendly(63));
  EXPECT_FALSE(fft_friendly(64));
  EXPECT_EQ(nearest_fft_friendly(30), 29);
  EXPECT_TRUE(fft_friendly(nearest_fft_friendly(100)));
}
