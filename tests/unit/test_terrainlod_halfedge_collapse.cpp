// collapse_halfedge against the operation it re-implements (OpenMesh's TriMesh::collapse):
// two copies of a mesh take the same random sequence of allowed collapses, one through the
// library and one through ours, and after every step the whole connectivity must agree
// (every half-edge's next, prev, to-vertex and face; every vertex's and face's half-edge;
// the deleted flags). The engine's order of work follows these handles, so agreement
// handle for handle is what keeps its results unchanged.

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh.hpp"
#include "terrainlod/collapse_check.hpp"
#include "terrainlod/halfedge_collapse.hpp"
#include "terrainlod_test_meshes.hpp"

namespace {

using fest::TriMesh;
using fest::test::first_difference;
using fest::test::grid_mesh;
using fest::terrainlod::CollapseCheck;
using fest::terrainlod::collapse_halfedge;


TEST(TerrainlodHalfedgeCollapse, MatchesOpenMeshHandleForHandle) {
  std::mt19937 rng(11);
  int collapses = 0, boundary_collapses = 0;
  for (int round = 0; round < 6; ++round) {
    TriMesh library = grid_mesh(10 + round, rng);
    TriMesh ours = library;
    CollapseCheck check(library.n_vertices());
    for (int step = 0; step < 4000; ++step) {
      const auto h = TriMesh::HalfedgeHandle(static_cast<int>(rng() % library.n_halfedges()));
      if (library.status(library.edge_handle(h)).deleted() || !check.collapse_ok(library, h)) continue;
      if (library.is_boundary(library.edge_handle(h))) ++boundary_collapses;
      library.collapse(h);
      collapse_halfedge(ours, h);
      ++collapses;
      const std::string diff = first_difference(library, ours);
      ASSERT_EQ(diff, "") << "round " << round << " step " << step;
    }
  }
  // Inner and boundary collapses both exercised, down to small remnants.
  EXPECT_GT(collapses, 300);
  EXPECT_GT(boundary_collapses, 30);
}

TEST(TerrainlodHalfedgeCollapse, InnerVertexCollapseRemovesTwoTrianglesAndOneVertex) {
  // 3 x 3 grid, SW-NE diagonals: the centre (valence 6) onto its east neighbour.
  TriMesh m = fest::test::ne_grid_mesh(3);
  std::vector<TriMesh::VertexHandle> v(m.vertices().begin(), m.vertices().end());
  collapse_halfedge(m, m.find_halfedge(v[4], v[5]));
  int live_faces = 0, live_vertices = 0;
  for (auto f : m.all_faces()) live_faces += !m.status(f).deleted();
  for (auto u : m.all_vertices()) live_vertices += !m.status(u).deleted();
  EXPECT_EQ(live_faces, 6);  // 8 - the two triangles on edge 4-5
  EXPECT_EQ(live_vertices, 8);
  EXPECT_TRUE(m.status(v[4]).deleted());
  // Vertex 5 now has the ring 2, 1, 0, 3, 7, 8 (every former neighbour of 4 and of 5).
  std::vector<int> ring;
  for (auto u : m.vv_range(v[5])) ring.push_back(u.idx());
  std::sort(ring.begin(), ring.end());
  EXPECT_EQ(ring, (std::vector<int>{0, 1, 2, 3, 7, 8}));
}

}  // namespace
