// The fdm transforms' product (docs/fluidsim.md §6): one summation order per element, so
// the kernel equals a plain j-ascending loop bit for bit and any split of rows or columns
// gives the same bytes; and the box solve gives the same bytes for any team size.
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <omp.h>

#include "fluidsim/dense_product.hpp"
#include "fluidsim/diffusion.hpp"
#include "fluidsim/projection.hpp"

using namespace fest::fluidsim;

namespace {

std::vector<double> random_values(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = u(rng);
  return v;
}

bool same_bytes(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace

TEST(FluidsimDenseProduct, EqualsTheAscendingSumBitForBit) {
  // Ragged sizes: a last block of fewer than 8 rows and an odd last column.
  for (int rows : {1, 7, 8, 13, 33}) {
    for (int cols : {1, 2, 5}) {
      const int depth = 11;
      const auto P = random_values(static_cast<std::size_t>(rows) * depth, 1);
      const auto Q = random_values(static_cast<std::size_t>(cols) * depth, 2);
      std::vector<double> Y(static_cast<std::size_t>(rows) * cols), ref(Y.size());
      // P(i, j) = P[i * depth + j] (rows strided), Q(r, j) = Q[r + j * cols].
      dense_product(P.data(), depth, 1, Q.data(), 1, cols, Y.data(), rows, rows, cols, depth);
      for (int r = 0; r < cols; ++r)
        for (int i = 0; i < rows; ++i) {
          double s = 0.0;
          for (int j = 0; j < depth; ++j) s += P[static_cast<std::size_t>(i) * depth + j] * Q[r + static_cast<std::size_t>(j) * cols];
          ref[i + static_cast<std::size_t>(r) * rows] = s;
        }
      EXPECT_TRUE(same_bytes(Y, ref)) << rows << "x" << cols;
      // The same product in two row pieces and two column pieces.
      std::vector<double> Z(Y.size());
      const int ri = rows / 2, rc = cols / 2;
      for (int part = 0; part < 4; ++part) {
        const int i0 = part & 1 ? ri : 0, i1 = part & 1 ? rows : ri;
        const int c0 = part & 2 ? rc : 0, c1 = part & 2 ? cols : rc;
        if (i1 > i0 && c1 > c0)
          dense_product(P.data() + static_cast<std::size_t>(i0) * depth, depth, 1, Q.data() + c0, 1, cols,
                        Z.data() + i0 + static_cast<std::size_t>(c0) * rows, rows, i1 - i0, c1 - c0, depth);
      }
      EXPECT_TRUE(same_bytes(Z, ref)) << rows << "x" << cols << " in pieces";
    }
  }
}

TEST(FluidsimDenseProduct, SolvesGiveTheSameBytesForAnyTeamSize) {
  // Boxes above the parallel threshold with ragged pieces; closed (tridiagonal z) and
  // periodic (dense z) axes; the projection's classes and a diffusion solve.
  const int saved = omp_get_max_threads();
  for (Boundary bc : {Boundary::closed, Boundary::periodic}) {
    const Layout L = Layout::make(3, {33, 34, 31}, {bc, bc, bc}, 0.05);
    for (PoissonSolver solver : {PoissonSolver::fdm, PoissonSolver::fft}) {
      ProjectionOptions po;
      po.solver = solver;
      const Projector proj(L, po);
      const Diffuser diff(L, 0.01, solver == PoissonSolver::fft ? Transform::fftw : Transform::dense, false);
      const Field rhs = random_values(L.count(), 3);
      std::vector<Field> q(3), d(3);
      for (int t = 1; t <= 3; ++t) {
        omp_set_num_threads(t);
        proj.solve(rhs, q[t - 1]);
        d[t - 1] = rhs;
        diff.velocity(1, d[t - 1]);
        // All components at once (one stage loop over the three boxes): the same bytes.
        Velocity u{rhs, rhs, rhs};
        diff.velocity(u);
        EXPECT_TRUE(same_bytes(u[1], d[t - 1])) << poisson_name(solver) << " components together, team of " << t;
      }
      for (int t = 2; t <= 3; ++t) {
        EXPECT_TRUE(same_bytes(q[0], q[t - 1])) << poisson_name(solver) << " projection, team of " << t;
        EXPECT_TRUE(same_bytes(d[0], d[t - 1])) << poisson_name(solver) << " diffusion, team of " << t;
      }
    }
  }
  omp_set_num_threads(saved);
}
