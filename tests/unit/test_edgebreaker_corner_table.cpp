// The corner table and the checks that keep the coder inside the chapter's setting
// (lib/edgebreaker/corner_table.cpp). Each rejected mesh is built to have exactly one defect.
#include <gtest/gtest.h>

#include "edgebreaker/corner_table.hpp"
#include "expect_error.hpp"
#include "test_edgebreaker_meshes.hpp"

using namespace fest::edgebreaker;
using fest::test::expect_bad_input;
namespace eb = fest::test::eb;

TEST(EdgebreakerCornerTable, OppositesOfTheTetrahedron) {
  const eb::Faces m = eb::tetrahedron();
  const CornerTable t = build_corner_table(m.triangles, m.vertex_count);
  ASSERT_EQ(t.corners(), 12);
  for (int c = 0; c < 12; ++c) {
    const int o = t.O[c];
    ASSERT_GE(o, 0);
    EXPECT_EQ(t.O[o], c);            // an involution
    EXPECT_NE(o / 3, c / 3);         // across to another triangle
    EXPECT_EQ(t.V[next(o)], t.V[prev(c)]);  // the shared edge, run the other way
    EXPECT_EQ(t.V[prev(o)], t.V[next(c)]);
  }
  // Corner 0 (vertex 0 of face 0 1 2) faces edge 1-2, shared with face 1 3 2 (triangle 3),
  // whose corner at vertex 3 is corner 10.
  EXPECT_EQ(t.O[0], 10);
}

TEST(EdgebreakerCornerTable, RejectsMeshesOutsideTheSetting) {
  using T = std::vector<Triangle>;
  const auto reject = [](const T& tris, int v, const std::string& needle) {
    expect_bad_input([&] { build_corner_table(tris, v); }, needle);
    expect_bad_input([&] { encode(tris, v); }, needle);  // encode checks through the same path
  };
  const T tetra = eb::tetrahedron().triangles;
  reject({}, 0, "no triangles");
  reject(tetra, -1, "negative");
  reject(tetra, 3, "refers to vertex 3, outside 0..2");
  reject({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 3}}, 4, "degenerate");
  reject({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}}, 4, "the mesh is open");                 // a face missing
  reject({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 2, 3}}, 4, "inconsistently oriented");  // one face flipped
  reject({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}, {1, 3, 2}}, 4, "same direction");  // duplicated face
  reject({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}, 5, "non-manifold edge");               // three faces on 0-1
  // Two tetrahedra sharing vertex 0 (a bow-tie): every edge is fine, the vertex is not.
  reject({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}, {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}}, 7,
         "vertex 0 is non-manifold: its triangles form 2 separate fans");
  reject({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}, {4, 5, 6}, {4, 7, 5}, {4, 6, 7}, {5, 7, 6}}, 8,
         "more than one connected component");
  reject({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}, 5, "vertex 4 is used by no triangle");
}

// A 4 x 4 grid glued into a torus: closed, manifold, simple, genus 1 (chi = 16 - 48 + 32 = 0).
TEST(EdgebreakerCornerTable, RejectsTheTorusByGenus) {
  std::vector<Triangle> tris;
  const auto at = [](int i, int j) { return ((i + 4) % 4) * 4 + (j + 4) % 4; };
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      tris.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      tris.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  ASSERT_EQ(eb::sphere_defect(tris, 16), "Euler characteristic is not 2");
  expect_bad_input([&] { encode(tris, 16); }, "genus 1 (Euler characteristic 0)");
}
