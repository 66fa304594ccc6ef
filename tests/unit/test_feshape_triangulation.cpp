// lib/feshape/triangulation + stiffness: the lat-long start mesh (V = mn + 2,
// F = 2V - 4, closed, outward), seam handling, and K's analytic properties.
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "feshape/model.hpp"
#include "feshape/stiffness.hpp"
#include "feshape/triangulation.hpp"

using namespace fest::feshape;

namespace {

// Every directed edge once, and its reverse once: closed, manifold, consistently oriented.
void expect_closed_oriented(const Triangulation& t) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& f : t.tris)
    for (int i = 0; i < 3; ++i) ++directed[{f[i], f[(i + 1) % 3]}];
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1) << e.first << "-" << e.second;
    EXPECT_EQ(directed.count({e.second, e.first}), 1u) << "boundary edge " << e.first << "-" << e.second;
  }
}

double signed_volume(const std::vector<Eigen::Vector3d>& x, const Triangulation& t) {
  double v = 0;
  for (const auto& f : t.tris) v += x[f[0]].dot(x[f[1]].cross(x[f[2]])) / 6;
  return v;
}

}  // namespace

TEST(FeshapeTriangulation, SeedGridsHaveTheSeedCounts) {
  // The seed's initial meshes (docs/feshape.md §2.3): 27, 51, 66 (128 el.), 47 (90 el.),
  // 227, 627 (1250 el.), 402 (800 el.).
  const std::vector<std::array<int, 4>> grids{{5, 5, 27, 50},     {7, 7, 51, 98},     {8, 8, 66, 128},
                                              {9, 5, 47, 90},     {15, 15, 227, 450}, {25, 25, 627, 1250},
                                              {20, 20, 402, 800}, {16, 16, 258, 512}};
  for (const auto& g : grids) {
    const Triangulation t = lat_long_mesh(g[0], g[1]);
    EXPECT_EQ(t.nodes(), static_cast<std::size_t>(g[2]));
    EXPECT_EQ(t.elements(), static_cast<std::size_t>(g[3]));
    EXPECT_EQ(t.elements(), 2 * t.nodes() - 4);
    expect_closed_oriented(t);
    const Model m = make_model(g[0], g[1], {1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0}, Eigen::Vector3d::Zero(),
                               Eigen::Quaterniond::Identity());
    EXPECT_GT(signed_volume(m.node_positions(), t), 0) << "outward orientation";
  }
}

TEST(FeshapeTriangulation, SeamMidpointsAndUnwrapping) {
  EXPECT_NEAR(seam_midpoint_v(3.0, -3.0), -pi, 1e-12);  // across the seam: (3 + 3.283)/2 - 2 pi
  EXPECT_NEAR(seam_midpoint_v(-1.0, 1.0), 0.0, 1e-15);
  const Triangulation t = lat_long_mesh(4, 6);
  for (std::size_t f = 0; f < t.elements(); ++f) {
    const auto c = unwrapped_corners(t, static_cast<int>(f));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_LE(std::abs(c[i][1] - c[j][1]), pi / 3 + 1e-12) << "element " << f;
  }
}

TEST(FeshapeStiffness, LumpedMassSumsToTheParameterDomainArea) {
  // Interior strips 2 pi (m - 1) h and two pole fans pi h each, h = pi / (m + 1):
  // 2 pi^2 m / (m + 1).
  for (int m : {3, 5, 8, 20}) {
    const Eigen::VectorXd mass = lumped_mass(lat_long_mesh(m, 7));
    EXPECT_NEAR(mass.sum(), 2 * pi * pi * m / (m + 1), 1e-10);
  }
}

TEST(FeshapeStiffness, ConstantsFeelOnlyTheZerothOrderTerm) {
  const Triangulation t = lat_long_mesh(6, 9);
  const StiffnessWeights w{0.3, 0.5, 0.7, 0.2, 0.1, 0.4};
  const Eigen::SparseMatrix<double> k = assemble_stiffness(t, w);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(k.rows());
  // Gradients of a constant vanish, so K 1 = w00 M 1.
  EXPECT_NEAR((k * ones - w.w00 * lumped_mass(t)).norm(), 0.0, 1e-10);
  EXPECT_NEAR((Eigen::MatrixXd(k) - Eigen::MatrixXd(k).transpose()).norm(), 0.0, 1e-10);
  // Positive semi-definite; a linear-in-u field has membrane energy w10 * area.
  Eigen::VectorXd lin(k.rows());
  for (Eigen::Index i = 0; i < lin.size(); ++i) lin[i] = t.u[static_cast<std::size_t>(i)];
  const StiffnessWeights membrane_u{0, 0, 1, 0, 0, 0};
  EXPECT_NEAR(lin.dot(assemble_stiffness(t, membrane_u) * lin), lumped_mass(t).sum(), 1e-9);
}
