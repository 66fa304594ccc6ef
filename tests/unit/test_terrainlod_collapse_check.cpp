// CollapseCheck against the definition it re-implements (OpenMesh's is_collapse_ok) and
// against small cases decided by hand: a lone triangle cannot lose an edge, an inner
// vertex of a grid can collapse onto a neighbour, and an inner edge between two boundary
// vertices cannot be collapsed.

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh.hpp"
#include "terrainlod/collapse_check.hpp"
#include "terrainlod_test_meshes.hpp"

namespace {

using fest::TriMesh;
using fest::terrainlod::CollapseCheck;
using fest::test::grid_mesh;


TEST(TerrainlodCollapseCheck, LoneTriangleKeepsItsEdges) {
  TriMesh m;
  m.request_vertex_status();
  m.request_edge_status();
  m.request_face_status();
  const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0});
  m.add_face(a, b, c);
  CollapseCheck check(m.n_vertices());
  for (auto h : m.halfedges()) EXPECT_FALSE(check.collapse_ok(m, h));
}

TEST(TerrainlodCollapseCheck, InnerVertexOfGridCollapsesLinkViolationRefused) {
  // 3 x 3 grid, all diagonals SW-NE: the centre 4 has neighbours 1, 3, 5, 7, 0, 8.
  TriMesh m = fest::test::ne_grid_mesh(3);
  std::vector<TriMesh::VertexHandle> v(m.vertices().begin(), m.vertices().end());
  CollapseCheck check(m.n_vertices());
  // Centre onto its east neighbour: common neighbours of 4 and 5 are 2 and 8, exactly the
  // two triangles' far corners.
  EXPECT_TRUE(check.collapse_ok(m, m.find_halfedge(v[4], v[5])));
  // Boundary vertex 1 onto the centre over an inner edge between a boundary and an inner
  // vertex: allowed (only boundary-boundary inner edges are refused).
  EXPECT_TRUE(check.collapse_ok(m, m.find_halfedge(v[1], v[4])));
  // Corner 0 onto the centre over the inner edge 0-4: only 4's side is inside, and 0 and 4
  // share exactly the far corners 1 and 3: allowed.
  EXPECT_TRUE(check.collapse_ok(m, m.find_halfedge(v[0], v[4])));
  // Collapse 4 onto 5; afterwards 5's neighbours are 1, 2, 3, 7, 8, 0 and the inner edge
  // 3-5 joins two boundary vertices: refused.
  m.collapse(m.find_halfedge(v[4], v[5]));
  EXPECT_FALSE(check.collapse_ok(m, m.find_halfedge(v[3], v[5])));
  EXPECT_FALSE(check.collapse_ok(m, m.find_halfedge(v[5], v[3])));
  // Boundary edge 0-1: triangle (0, 1, 5) has edges 1-5 and 5-0 inside, so allowed by the
  // side test; 0 and 1 share neighbour 5 only (the far corner): allowed.
  EXPECT_TRUE(check.collapse_ok(m, m.find_halfedge(v[0], v[1])));
}

TEST(TerrainlodCollapseCheck, AgreesWithOpenMeshOverRandomCollapseSequences) {
  std::mt19937 rng(7);
  int agreed_true = 0, agreed_false = 0;
  for (int round = 0; round < 8; ++round) {
    TriMesh m = grid_mesh(12, rng);
    CollapseCheck check(m.n_vertices());
    for (int step = 0; step < 3000; ++step) {
      const auto h = TriMesh::HalfedgeHandle(static_cast<int>(rng() % m.n_halfedges()));
      if (m.status(m.edge_handle(h)).deleted()) continue;  // the check's precondition: a live half-edge
      const bool ours = check.collapse_ok(m, h);
      ASSERT_EQ(ours, m.is_collapse_ok(h)) << "round " << round << " step " << step;
      (ours ? agreed_true : agreed_false)++;
      if (ours && rng() % 3 == 0) m.collapse(h);
    }
  }
  // Both answers must have been exercised many times.
  EXPECT_GT(agreed_true, 500);
  EXPECT_GT(agreed_false, 500);
}

}  // namespace
