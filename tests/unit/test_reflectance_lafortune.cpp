#include "reflectance/lafortune.hpp"

#include <cmath>

#include <Eigen/LU>
#include <gtest/gtest.h>

using fest::reflectance::LafortuneBrdf;
using fest::reflectance::LafortuneLobe;
using fest::reflectance::Rgb;

TEST(Lafortune, DiffuseOnlyIsAlbedoOverPi) {
  LafortuneBrdf b;
  b.rho_d = Rgb(0.5, 0.25, 1.0);
  const Rgb f = evaluate(b, Eigen::Vector3d(0.6, 0, 0.8), Eigen::Vector3d(0, 0.6, 0.8));
  EXPECT_NEAR(f[0], 0.5 / M_PI, 1e-15);
  EXPECT_NEAR(f[2], 1.0 / M_PI, 1e-15);
}

TEST(Lafortune, MirrorLobePeaksAtTheMirrorDirection) {
  // Cxy = -1, Cz = 1 makes the base the cosine between v and u mirrored about n, so the
  // lobe is a Phong lobe: 1 at the mirror direction, cos^N alpha away from it.
  LafortuneBrdf b;
  b.lobes = {LafortuneLobe{Rgb::Constant(-1), Rgb::Constant(1), Rgb::Constant(20)}};
  const Eigen::Vector3d u = Eigen::Vector3d(0.6, 0, 0.8);
  const Eigen::Vector3d mirror(-0.6, 0, 0.8);
  EXPECT_NEAR(evaluate(b, u, mirror)[1], 1.0, 1e-14);
  const double a = 0.2;
  const Eigen::Vector3d off(-std::sin(std::asin(0.6) + a), 0, std::cos(std::asin(0.6) + a));
  EXPECT_NEAR(evaluate(b, u, off)[1], std::pow(std::cos(a), 20), 1e-12);
}

TEST(Lafortune, NegativeBaseIsClampedToZero) {
  LafortuneBrdf b;
  b.lobes = {LafortuneLobe{Rgb::Constant(-1), Rgb::Constant(1), Rgb::Constant(2.5)}};
  // u and v on the same side of the normal-tangent plane: the mirrored cosine is negative.
  const Rgb f = evaluate(b, Eigen::Vector3d(0.99, 0, 0.141), Eigen::Vector3d(0.99, 0, 0.141));
  EXPECT_TRUE(f.allFinite());
  EXPECT_EQ(f[0], 0.0);
}

TEST(Lafortune, LocalFrameIsOrthonormalAndRightHanded) {
  for (const Eigen::Vector3d& n : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 2, 3).normalized(),
                                  Eigen::Vector3d(-1, 0, 0)}) {
    const Eigen::Matrix3d f = fest::reflectance::local_frame(n);
    EXPECT_NEAR((f.transpose() * f - Eigen::Matrix3d::Identity()).norm(), 0, 1e-14);
    EXPECT_NEAR(f.determinant(), 1, 1e-14);
    EXPECT_NEAR((f.col(2) - n).norm(), 0, 0);
  }
}
