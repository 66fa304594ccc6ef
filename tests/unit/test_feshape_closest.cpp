// lib/feshape/closest + assignment: the AABB tree equals brute force; barycentric
// answers on constructed points; error statistics by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "core/rng.hpp"
#include "feshape/assignment.hpp"
#include "feshape/model.hpp"

using namespace fest::feshape;

TEST(FeshapeClosest, TreeEqualsBruteForce) {
  const Model m = make_model(12, 15, {1.5, 0.6, 0.8, 1, 0.7, 1.4, 0.2, 0, 0.2, 0, 0.5}, Eigen::Vector3d(0.1, 0, 0),
                             Eigen::Quaterniond::Identity());
  const std::vector<Eigen::Vector3d> x = m.node_positions();
  fest::Rng rng(11);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 10000; ++i) pts.emplace_back(rng.uniform(-2.5, 2.5), rng.uniform(-2.5, 2.5), rng.uniform(-2.5, 2.5));
  const auto tree = assign_points(pts, x, m.mesh.tris, 2);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const MeshPoint b = closest_brute_force(pts[i], x, m.mesh.tris);
    ASSERT_NEAR(tree[i].dist, b.dist, 1e-12) << "point " << i;
  }
  // Any thread count gives the same answer.
  const auto one = assign_points(pts, x, m.mesh.tris, 1);
  for (std::size_t i = 0; i < pts.size(); ++i) ASSERT_EQ(one[i].face, tree[i].face);
}

TEST(FeshapeClosest, RegionsOfATriangle) {
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  auto q = closest_on_triangle(Eigen::Vector3d(0.5, 0.5, 3), a, b, c);  // above the inside
  EXPECT_NEAR(q.dist2, 9, 1e-12);
  EXPECT_NEAR(q.lambda[1], 0.25, 1e-12);
  EXPECT_NEAR(q.lambda[2], 0.25, 1e-12);
  q = closest_on_triangle(Eigen::Vector3d(1, -1, 0), a, b, c);  // beside edge ab
  EXPECT_NEAR(q.dist2, 1, 1e-12);
  EXPECT_NEAR(q.lambda[2], 0, 1e-15);
  q = closest_on_triangle(Eigen::Vector3d(-1, -1, 0), a, b, c);  // beyond vertex a
  EXPECT_EQ(q.lambda[0], 1);
  EXPECT_NEAR(q.dist2, 2, 1e-12);
  q = closest_on_triangle(Eigen::Vector3d(2, 2, 0), a, b, c);  // beside the hypotenuse
  EXPECT_NEAR(q.dist2, 2, 1e-12);
  EXPECT_NEAR(q.lambda[0], 0, 1e-15);
}

TEST(FeshapeClosest, ErrorStatisticsByHand) {
  std::vector<MeshPoint> p(4);
  const double d[4] = {1, 2, 3, 6};
  for (int i = 0; i < 4; ++i) p[i].dist = d[i];
  const ErrorStats s = error_stats(p);
  EXPECT_DOUBLE_EQ(s.mean, 3);
  EXPECT_DOUBLE_EQ(s.max, 6);
  EXPECT_DOUBLE_EQ(s.var, (4 + 1 + 0 + 9) / 4.0);
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(3.5));
}
