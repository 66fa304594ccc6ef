// add_triangle against the operation it re-implements (OpenMesh's TriMesh::add_face):
// the triangles of random grid meshes (and of a fan around one vertex) are added in random
// orders to two meshes, one through the library and one through ours; after every
// triangle the answer (a face or a refusal) and the whole connectivity must agree. Random
// orders make the library re-link boundary patches and refuse faces, not only append them.

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh.hpp"
#include "terrainlod/mesh_add_face.hpp"
#include "terrainlod_test_meshes.hpp"

namespace {

using fest::TriMesh;
using fest::test::first_difference;
using fest::terrainlod::add_triangle;

TriMesh empty_mesh(int vertices) {
  TriMesh m;
  m.request_vertex_status();
  m.request_edge_status();
  m.request_face_status();
  for (int k = 0; k < vertices; ++k) m.add_vertex(TriMesh::Point(k, 0, 0));
  return m;
}


// The counter-clockwise triangles of an n x n grid, each cell split by a random diagonal.
std::vector<std::array<int, 3>> grid_triangles(int n, std::mt19937& rng) {
  std::vector<std::array<int, 3>> t;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = a + n + 1;
      if (rng() & 1) {
        t.push_back({a, b, d});
        t.push_back({a, d, c});
      } else {
        t.push_back({a, b, c});
        t.push_back({b, d, c});
      }
    }
  return t;
}

// Adds `triangles` in order to both meshes, comparing after each; counts the refusals.
int add_all_and_compare(int vertices, const std::vector<std::array<int, 3>>& triangles) {
  TriMesh library = empty_mesh(vertices), ours = empty_mesh(vertices);
  int refused = 0;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const auto& t = triangles[k];
    const auto fl = library.add_face(TriMesh::VertexHandle(t[0]), TriMesh::VertexHandle(t[1]), TriMesh::VertexHandle(t[2]));
    const auto fo = add_triangle(ours, TriMesh::VertexHandle(t[0]), TriMesh::VertexHandle(t[1]), TriMesh::VertexHandle(t[2]));
    EXPECT_EQ(fl, fo) << "triangle " << k;
    refused += !fl.is_valid();
    const std::string diff = first_difference(library, ours);
    EXPECT_EQ(diff, "") << "after triangle " << k;
    if (!diff.empty() || fl != fo) return -1;
  }
  return refused;
}

TEST(TerrainlodMeshAddFace, GridInRowOrderMatchesOpenMesh) {
  std::mt19937 rng(3);
  const auto t = grid_triangles(9, rng);
  EXPECT_EQ(add_all_and_compare(81, t), 0);  // row order never needs a refusal
}

TEST(TerrainlodMeshAddFace, GridInRandomOrdersMatchesOpenMesh) {
  std::mt19937 rng(5);
  int refused = 0;
  for (int round = 0; round < 40; ++round) {
    const int n = 4 + round % 7;
    auto t = grid_triangles(n, rng);
    std::shuffle(t.begin(), t.end(), rng);
    // Then some of them again: each is refused (its sides already have faces), and the
    // refusals must leave both meshes as they were.
    const std::size_t m = t.size();
    for (std::size_t k = 0; k < 5; ++k) t.push_back(t[rng() % m]);
    const int r = add_all_and_compare(n * n, t);
    ASSERT_GE(r, 0) << "round " << round;
    refused += r;
  }
  EXPECT_EQ(refused, 40 * 5);  // only the repeats
}

TEST(TerrainlodMeshAddFace, ClosingAFanRelinksAndFinishesTheVertex) {
  // Six triangles around vertex 0 (ring 1..6), added in the order 0, 2, 4, 1, 3, 5: the
  // later ones join existing boundary patches. Afterwards 0 is an inner vertex.
  std::vector<std::array<int, 3>> fan;
  for (int k = 0; k < 6; ++k) fan.push_back({0, 1 + k, 1 + (k + 1) % 6});
  const std::vector<std::array<int, 3>> order{fan[0], fan[2], fan[4], fan[1], fan[3], fan[5]};
  EXPECT_EQ(add_all_and_compare(7, order), 0);
  TriMesh m = empty_mesh(7);
  for (const auto& t : order)
    add_triangle(m, TriMesh::VertexHandle(t[0]), TriMesh::VertexHandle(t[1]), TriMesh::VertexHandle(t[2]));
  EXPECT_FALSE(m.is_boundary(TriMesh::VertexHandle(0)));
  EXPECT_EQ(m.valence(TriMesh::VertexHandle(0)), 6u);
  EXPECT_EQ(m.n_faces(), 6u);
  EXPECT_EQ(m.n_edges(), 12u);  // 6 spokes + 6 ring edges
}

}  // namespace
