// Flow probes against analytic answers: in a rigid rotation (rate 1 about z) with an
// axial drift, a ribbon around the axis keeps its width and twists at the rotation rate;
// half the streamwise vorticity equals that rate; glyph and tube meshes are closed
// shapes of the expected size.

#include <cmath>

#include <gtest/gtest.h>

#include "lemtrace/field_grid.hpp"
#include "lemtrace/generate.hpp"
#include "lemtrace/probes.hpp"
#include "lemtrace/tracer.hpp"

using namespace fest::lemtrace;

namespace {

FieldGrid helix_grid() {
  GenOptions o;
  o.kind = "helix";  // v = (-y, x, 0.05): rotation rate 1 about z, axial speed 0.05
  o.n = 20;
  GeneratedGrid g = generate(o);
  return FieldGrid(build_tet_mesh(g.points, g.vectors, g.cells, BuildOptions{}, nullptr), ClassifyParams{},
                   Precompute::lazy, 1);
}

}  // namespace

TEST(LemtraceProbes, RibbonInRigidRotationKeepsWidthAndTwistsAtTheRate) {
  const FieldGrid grid = helix_grid();
  TraceOptions o;
  o.max_time = 25;          // about four turns
  o.samples_per_cell = 16;  // closed-form points inside cells, so pairing by time is tight
  const Vec3 seed(0, 0, -0.8);
  const double w = 0.1;
  const Vec3 offset = w * perpendicular(Vec3(0, 0, 0.05));
  const Polyline main = trace(grid, seed, 0.0, o);
  const Polyline side = trace(grid, seed + offset, 0.0, o);
  const auto edges = ribbon_edges(main, side);
  ASSERT_GT(edges.size(), 20u);
  EXPECT_GT(edges.back().t, 24.0);
  for (const auto& e : edges) {
    EXPECT_NEAR(e.width, w, 2e-3 * w) << "t=" << e.t;
    EXPECT_NEAR(e.twist, e.t, 2e-3 * std::max(1.0, e.t)) << "t=" << e.t;  // Omega = 1
  }
  // The theory's rate: half the streamwise vorticity of v = A x + b, on the axis.
  Eigen::Matrix3d A;
  A << 0, -1, 0, 1, 0, 0, 0, 0, 0;
  EXPECT_NEAR(0.5 * streamwise_vorticity(A, Vec3(0, 0, 0.05)), 1.0, 1e-12);

  ProbeMesh mesh;
  append_ribbon(mesh, edges);
  EXPECT_EQ(mesh.points.size(), 2 * edges.size());
  EXPECT_EQ(mesh.triangles.size(), 2 * (edges.size() - 1));
  ASSERT_EQ(mesh.scalar_names.size(), 3u);
  for (const auto& s : mesh.scalars) EXPECT_EQ(s.size(), mesh.points.size());
}

TEST(LemtraceProbes, ArrowsPointAlongTheirDirection) {
  ProbeMesh mesh;
  const Vec3 p(1, 2, 3), dir(0, 3, 4);
  append_arrow(mesh, p, dir, 2.0, 0.1, 8, "pressure", 7.5);
  ASSERT_EQ(mesh.points.size(), 3u * 8 + 2);
  EXPECT_EQ(mesh.triangles.size(), 6u * 8);
  // The tip is p + length * dir/|dir|; every vertex lies between base and tip plane.
  const Vec3 tip = mesh.points[3 * 8];
  EXPECT_NEAR((tip - (p + 2.0 * dir.normalized())).norm(), 0.0, 1e-12);
  for (const auto& v : mesh.points) {
    const double along = (v - p).dot(dir.normalized());
    EXPECT_GE(along, -1e-12);
    EXPECT_LE(along, 2.0 + 1e-12);
  }
  for (double s : mesh.scalars[mesh.scalar("pressure")]) EXPECT_EQ(s, 7.5);
}

TEST(LemtraceProbes, TubeHasTheRadius) {
  Polyline line;
  for (int i = 0; i <= 20; ++i) {
    const double a = 0.1 * i;
    line.x.push_back(Vec3(std::cos(a), std::sin(a), 0.2 * a));
    line.t.push_back(a);
  }
  ProbeMesh mesh;
  append_tube(mesh, line, 0.05, 12, "speed", std::vector<double>(line.x.size(), 1.0));
  ASSERT_EQ(mesh.points.size(), 21u * 12);
  for (std::size_t i = 0; i < line.x.size(); ++i)
    for (int k = 0; k < 12; ++k) EXPECT_NEAR((mesh.points[i * 12 + static_cast<std::size_t>(k)] - line.x[i]).norm(), 0.05, 1e-12);
}
