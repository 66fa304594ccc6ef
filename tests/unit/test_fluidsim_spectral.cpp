// Fast diagonalization (docs/fluidsim.md §4): the FFTW transforms have the eigenvalues
// of the assembled 1-D operators, and one implicit diffusion step scales a discrete
// eigenmode by exactly 1/(1 + nu dt mu) (test 6).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "fluidsim/diffusion.hpp"
#include "fluidsim/projection.hpp"
#include "fluidsim/spectral.hpp"

using namespace fest::fluidsim;

namespace {
std::vector<double> sorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v;
}
}  // namespace

TEST(FluidsimSpectral, FftEigenvaluesMatchTheOperator) {
  // Closed n even and odd (DCT-I, DCT-II and the whole/half DCT-V classes), periodic
  // even and odd, and the Dirichlet (DST-I) interior of an odd field.
  for (int n : {8, 9}) {
    for (Boundary bc : {Boundary::closed, Boundary::periodic}) {
      const Layout L = Layout::make(2, {n, n, 1}, {bc, bc, bc}, 0.1);
      for (int p = 0; p < classes_along(L, 0, 2); ++p) {
        const AxisBasis dense(L, 0, class_nodes(L, 0, p, 2), 2, Parity::even, Transform::dense);
        const AxisBasis fft(L, 0, class_nodes(L, 0, p, 2), 2, Parity::even, Transform::fftw);
        EXPECT_TRUE(fft.uses_fftw());
        const auto a = sorted(dense.eigenvalues()), b = sorted(fft.eigenvalues());
        for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-9 * std::fabs(a.front())) << n << " " << p;
      }
    }
    const Layout L = Layout::make(2, {n, n, 1}, {Boundary::closed, Boundary::closed, Boundary::closed}, 0.1);
    std::vector<int> interior;
    for (int i = 1; i <= n; ++i) interior.push_back(i);
    const AxisBasis dense(L, 0, interior, 1, Parity::odd, Transform::dense);
    const AxisBasis fft(L, 0, interior, 1, Parity::odd, Transform::fftw);
    const auto a = sorted(dense.eigenvalues()), b = sorted(fft.eigenvalues());
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-9 * std::fabs(a.front()));
  }
}

TEST(FluidsimSpectral, DiffusionScalesACosineModeExactly) {
  // s = cos(pi k i / (n+1)) on nodes 0..n+1 is an eigenvector of the Neumann compact
  // Laplacian with mu = -(4/h^2) sin^2(pi k / (2 (n+1))).
  const int n = 14;
  const double h = 1.0 / (n + 1), c = 0.37;
  const Layout L = Layout::make(2, {n, n, 1}, {Boundary::closed, Boundary::closed, Boundary::closed}, h);
  for (Transform kind : {Transform::dense, Transform::fftw}) {
    const Diffuser D(L, c, kind, false);
    Field s = L.zeros(), expect = L.zeros();
    const int kx = 3, ky = 5;
    const double mu = -4.0 / (h * h) *
                      (std::pow(std::sin(M_PI * kx / (2.0 * (n + 1))), 2) + std::pow(std::sin(M_PI * ky / (2.0 * (n + 1))), 2));
    for (int j = 0; j < L.size[1]; ++j)
      for (int i = 0; i < L.size[0]; ++i) {
        s[L.index(i, j, 0)] = std::cos(M_PI * kx * i / (n + 1)) * std::cos(M_PI * ky * j / (n + 1));
        expect[L.index(i, j, 0)] = s[L.index(i, j, 0)] / (1.0 - c * mu);
      }
    D.scalar(s);
    for (std::size_t k = 0; k < s.size(); ++k) EXPECT_NEAR(s[k], expect[k], 1e-12);
  }
}
