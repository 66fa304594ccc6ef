// lib/feshape/refine: Rivara bisection keeps the mesh conforming and closed
// (F = 2V - 4), bounds the smallest angle, leaves far elements alone, never moves the
// surface; the selection rule of §2.1.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "core/error.hpp"

#include "core/rng.hpp"
#include "feshape/model.hpp"
#include "feshape/refine.hpp"

using namespace fest::feshape;

namespace {

void expect_conforming(const Triangulation& t) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& f : t.tris)
    for (int i = 0; i < 3; ++i) ++directed[{f[i], f[(i + 1) % 3]}];
  for (const auto& [e, n] : directed) {
    ASSERT_EQ(n, 1);
    ASSERT_EQ(directed.count({e.second, e.first}), 1u) << "hanging node on edge " << e.first << "-" << e.second;
  }
}

double min_angle(const std::vector<Eigen::Vector3d>& x, const Triangulation& t) {
  double best = pi;
  for (const auto& f : t.tris)
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d a = x[f[(i + 1) % 3]] - x[f[i]], b = x[f[(i + 2) % 3]] - x[f[i]];
      best = std::min(best, std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)));
    }
  return best;
}

}  // namespace

TEST(FeshapeRefine, RandomSelectionsOverTenLevelsStayConformingAndClosed) {
  Model m = make_model(6, 6, {1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0}, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
  std::vector<Eigen::Vector3d> x = m.node_positions();
  const double alpha0 = min_angle(x, m.mesh);
  fest::Rng rng(3);
  for (int level = 0; level < 10; ++level) {
    std::vector<char> selected(m.mesh.elements(), 0);
    for (auto& s : selected) s = rng.uniform() < 0.15;
    const std::size_t before_nodes = m.mesh.nodes();
    const std::vector<NewNode> created = rivara_refine(m.mesh, x, selected, 1000000);
    EXPECT_EQ(m.mesh.nodes(), before_nodes + created.size());
    EXPECT_EQ(m.mesh.elements(), 2 * m.mesh.nodes() - 4);
    expect_conforming(m.mesh);
    for (const NewNode& n : created) EXPECT_EQ(x[n.node], 0.5 * (x[n.a] + x[n.b])) << "midpoint, exactly";
    EXPECT_EQ(m.mesh.level.size(), m.mesh.elements());
  }
  // Longest-edge bisection bounds the angles (Rosenberg & Stenger): alpha >= alpha0 / 2.
  EXPECT_GE(min_angle(x, m.mesh), alpha0 / 2 - 1e-12);
}

TEST(FeshapeRefine, SelectingEverythingBisectsEveryElementOnce) {
  Triangulation t = lat_long_mesh(5, 8);
  Model m = make_model(5, 8, {1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0}, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
  std::vector<Eigen::Vector3d> x = m.node_positions();
  const std::size_t f0 = t.elements();
  rivara_refine(t, x, std::vector<char>(f0, 1), 1000000);
  // Every original element is split at least once: no element keeps level 0.
  EXPECT_EQ(std::count(t.level.begin(), t.level.end(), 0), 0);
  EXPECT_GE(t.elements(), 2 * f0);
  expect_conforming(t);
}

TEST(FeshapeRefine, ElementsFarFromTheSelectionAreUntouched) {
  Model m = make_model(10, 12, {1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0}, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
  std::vector<Eigen::Vector3d> x = m.node_positions();
  const Triangulation before = m.mesh;
  std::vector<char> selected(before.elements(), 0);
  selected[40] = 1;  // one element near the south
  rivara_refine(m.mesh, x, selected, 1000000);
  std::set<std::array<int, 3>> after(m.mesh.tris.begin(), m.mesh.tris.end());
  std::size_t kept = 0;
  for (std::size_t f = 0; f < before.elements(); ++f) {
    bool far = true;
    for (int i = 0; i < 3; ++i) far = far && x[before.tris[f][i]].z() > 0.5;  // the northern cap
    if (far) {
      EXPECT_TRUE(after.count(before.tris[f])) << "element " << f << " changed";
      ++kept;
    }
  }
  EXPECT_GT(kept, 20u);
}

TEST(FeshapeRefine, NodeLimitIsAFailure) {
  Triangulation t = lat_long_mesh(5, 5);
  Model m = make_model(5, 5, {1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0}, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
  std::vector<Eigen::Vector3d> x = m.node_positions();
  EXPECT_THROW(rivara_refine(t, x, std::vector<char>(t.elements(), 1), 30), fest::Error);
}

TEST(FeshapeRefine, SelectionCasesInsideEdgeNode) {
  const Triangulation t = lat_long_mesh(4, 6);
  const auto around = faces_around_nodes(t);
  auto count = [&](std::array<double, 3> lambda) {
    std::vector<char> s(t.elements(), 0);
    select_elements(t, MeshPoint{10, lambda, 1.0}, around, s);
    return std::count(s.begin(), s.end(), 1);
  };
  EXPECT_EQ(count({0.3, 0.3, 0.4}), 1);  // inside: the element
  EXPECT_EQ(count({0.0, 0.5, 0.5}), 2);  // on an edge: both elements
  const int node = t.tris[10][0];
  EXPECT_EQ(count({1.0, 0.0, 0.0}), static_cast<long>(around[node].size()));  // at a node: its ring
}

TEST(FeshapeRefine, NewNodesKeepTheSurfaceInPlace) {
  // displace_new_nodes: d_D makes x_D the midpoint of its edge on a tapered, bent model.
  Model m = make_model(6, 8, {2, 0.5, 0.7, 0.9, 0.8, 1.2, 0.3, -0.2, 0.3, 0.1, 0.5}, Eigen::Vector3d(1, 2, 3),
                       Eigen::Quaterniond(0.9, 0.1, 0.2, 0.3).normalized());
  std::vector<Eigen::Vector3d> x = m.node_positions();
  std::vector<char> selected(m.mesh.elements(), 0);
  for (std::size_t f = 0; f < selected.size(); f += 3) selected[f] = 1;
  const auto created = rivara_refine(m.mesh, x, selected, 100000);
  displace_new_nodes(m, x, created);
  for (const NewNode& n : created) EXPECT_NEAR((m.node_position(n.node) - 0.5 * (x[n.a] + x[n.b])).norm(), 0.0, 1e-12);
}
