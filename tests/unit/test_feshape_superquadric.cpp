// lib/feshape/superquadric: eqs. 2-3 against hand values, J and ds/du against central
// finite differences, the a_i gauge fold keeps the shape.
#include <cmath>

#include <gtest/gtest.h>

#include "core/rng.hpp"
#include "feshape/superquadric.hpp"

using namespace fest::feshape;

namespace {
constexpr double pi = 3.14159265358979323846;
}

TEST(FeshapeSuperquadric, UnitParametersGiveASphereOfRadiusA) {
  const GlobalParams q{2.5, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0};
  for (double u : {-1.2, -0.3, 0.0, 0.7, 1.5})
    for (double v : {-3.0, -1.0, 0.0, 2.0, 3.1}) {
      const Eigen::Vector3d s = shape(q, u, v);
      EXPECT_NEAR(s.norm(), 2.5, 1e-12);
      EXPECT_NEAR(s.z(), 2.5 * std::sin(u), 1e-12);
    }
}

TEST(FeshapeSuperquadric, HandValuesOfTaperingAndBending) {
  // u = pi/6: S_u = 1/2, C_u = sqrt(3)/2; v = 0: C_v = 1, S_v = 0; e1 = e2 = 1.
  const GlobalParams q{2, 0.5, 0.4, 1, 1, 1, 0.6, -0.2, 0.3, 0.1, 0.5};
  const Eigen::Vector3d s = shape(q, pi / 6, 0);
  const double e1 = 2 * 0.5 * std::sqrt(3.0) / 2;
  EXPECT_NEAR(s.x(), (0.6 * 0.5 + 1) * e1 + 0.3 * std::cos((0.5 + 0.1) * pi * 0.5), 1e-12);
  EXPECT_NEAR(s.y(), 0.0, 1e-12);
  EXPECT_NEAR(s.z(), 2 * 1 * 0.5, 1e-12);
  // Squareness: e1 = 2, u = pi/4 -> |sin u|^2 = 1/2.
  const GlobalParams sq{1, 1, 1, 1, 2, 1, 0, 0, 0, 0, 0};
  EXPECT_NEAR(shape(sq, pi / 4, 0).z(), 0.5, 1e-12);
}

TEST(FeshapeSuperquadric, JacobianMatchesCentralDifferences) {
  fest::Rng rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    GlobalParams q{rng.uniform(0.5, 3), rng.uniform(0.2, 1), rng.uniform(0.2, 1), rng.uniform(0.2, 1),
                   rng.uniform(0.3, 2.5), rng.uniform(0.3, 2.5), rng.uniform(-0.8, 0.8), rng.uniform(-0.8, 0.8),
                   rng.uniform(-1, 1), rng.uniform(-0.8, 0.8), rng.uniform(0.1, 0.9)};
    const double u = rng.uniform(-1.45, 1.45), v = rng.uniform(-3.1, 3.1);  // away from the poles and axes
    if (std::abs(std::sin(v)) < 0.05 || std::abs(std::cos(v)) < 0.05) continue;
    const auto j = shape_jacobian(q, u, v);
    for (int k = 0; k < n_global; ++k) {
      const double h = 1e-6 * std::max(1.0, std::abs(q[k]));
      GlobalParams qp = q, qm = q;
      qp[k] += h;
      qm[k] -= h;
      const Eigen::Vector3d fd = (shape(qp, u, v) - shape(qm, u, v)) / (2 * h);
      EXPECT_NEAR((j.col(k) - fd).norm(), 0.0, 1e-6 * std::max(1.0, fd.norm())) << "parameter " << global_names()[k];
    }
    const auto t = shape_tangents(q, u, v);
    const double h = 1e-6;
    EXPECT_NEAR((t.col(0) - (shape(q, u + h, v) - shape(q, u - h, v)) / (2 * h)).norm(), 0.0, 1e-5);
    EXPECT_NEAR((t.col(1) - (shape(q, u, v + h) - shape(q, u, v - h)) / (2 * h)).norm(), 0.0, 1e-5);
  }
}

TEST(FeshapeSuperquadric, JacobianIsFiniteAtThePolesAndAxes) {
  const GlobalParams q{1, 0.5, 0.6, 0.9, 0.7, 1.3, 0.1, 0.2, 0.1, 0, 0.5};
  for (double u : {-pi / 2, 0.0, pi / 2})
    for (double v : {-pi, -pi / 2, 0.0, pi / 2}) EXPECT_TRUE(shape_jacobian(q, u, v).allFinite());
}

TEST(FeshapeSuperquadric, FoldingAnAspectAboveOneKeepsTheShape) {
  const GlobalParams q{2, 0.5, 1.4, 0.8, 0.9, 1.1, 0.3, -0.2, 0.2, 0.1, 0.6};
  GlobalParams folded = q;
  clamp_global(folded);
  EXPECT_NEAR(folded[ia2], 1.0, 1e-15);
  EXPECT_NEAR(folded[ia], 2.8, 1e-12);
  for (double u : {-1.0, 0.2, 1.3})
    for (double v : {-2.0, 0.5, 2.5}) EXPECT_NEAR((shape(q, u, v) - shape(folded, u, v)).norm(), 0.0, 1e-12);
}

TEST(FeshapeSuperquadric, RangeCheckNamesTheParameter) {
  EXPECT_EQ(check_global({1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0}), "");
  EXPECT_NE(check_global({1, 0, 1, 1, 1, 1, 0, 0, 0, 0, 0}).find("a1"), std::string::npos);
  EXPECT_NE(check_global({1, 1, 1, 1, 0, 1, 0, 0, 0, 0, 0}).find("e1"), std::string::npos);
  EXPECT_NE(check_global({1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 2}).find("b3"), std::string::npos);
}
