#pragma once
// Shared by the test_mesh_*.cpp files: hand-built meshes whose content is known
// exactly, and exact mesh comparison.

#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/mesh.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::test {

// Vertex indices of every face, in the order the face lists them.
inline std::vector<std::vector<int>> face_lists(const Mesh& mesh) {
  std::vector<std::vector<int>> faces;
  for (auto f : mesh.faces()) {
    faces.emplace_back();
    for (auto v : mesh.fv_range(f)) faces.back().push_back(v.idx());
  }
  return faces;
}

// Same bits (so -0 differs from 0 and NaN equals itself).
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Counts, vertex order, coordinates bit for bit, and face connectivity.
inline void expect_same_geometry(const Mesh& expected, const Mesh& actual) {
  ASSERT_EQ(expected.n_vertices(), actual.n_vertices());
  ASSERT_EQ(expected.n_faces(), actual.n_faces());
  std::size_t mismatches = 0;
  for (auto v : expected.vertices()) {
    const auto& p = expected.point(v);
    const auto& q = actual.point(Mesh::VertexHandle(v.idx()));
    for (int k = 0; k < 3; ++k)
      if (!same_bits(p[k], q[k]) && mismatches++ < 5)
        ADD_FAILURE() << "vertex " << v.idx() << " coordinate " << k << ": " << p[k] << " became " << q[k];
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(face_lists(expected), face_lists(actual));
}

// A cube from -1 to 1 with six quads (outward, counter-clockwise) and face colours.
inline Mesh quad_cube() {
  Mesh mesh;
  std::vector<Mesh::VertexHandle> v;
  for (int i = 0; i < 8; ++i)
    v.push_back(mesh.add_vertex(Mesh::Point(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  mesh.request_face_colors();
  int n = 0;
  for (const auto& q : quads) {
    auto f = mesh.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
    mesh.set_color(f, Mesh::Color(static_cast<unsigned char>(40 * n), 255, static_cast<unsigned char>(7 * n)));
    ++n;
  }
  return mesh;
}

// A tetrahedron whose coordinates are doubles no float can hold (1/3, 0.1, pi...),
// with vertex normals, colours and texture coordinates.
inline Mesh attributed_tetrahedron() {
  Mesh mesh;
  mesh.request_vertex_normals();
  mesh.request_vertex_colors();
  mesh.request_vertex_texcoords2D();
  const double points[4][3] = {{1.0 / 3.0, 0.1, -0.0}, {3.141592653589793, 1e-300, 2.5}, {-7.25, 1e300, 0.2}, {0, 0, 1}};
  std::vector<Mesh::VertexHandle> v;
  for (int i = 0; i < 4; ++i) {
    v.push_back(mesh.add_vertex(Mesh::Point(points[i][0], points[i][1], points[i][2])));
    mesh.set_normal(v[i], Mesh::Normal(0.6, -0.8, i * 0.1));
    mesh.set_color(v[i], Mesh::Color(static_cast<unsigned char>(255 - i), static_cast<unsigned char>(i * 60), 1));
    mesh.set_texcoord2D(v[i], Mesh::TexCoord2D(0.1f * static_cast<float>(i), 1.0f / 3.0f));
  }
  mesh.add_face(v[0], v[2], v[1]);
  mesh.add_face(v[0], v[1], v[3]);
  mesh.add_face(v[1], v[2], v[3]);
  mesh.add_face(v[2], v[0], v[3]);
  return mesh;
}

inline void expect_same_vertex_attributes(const Mesh& expected, const Mesh& actual) {
  ASSERT_TRUE(actual.has_vertex_normals());
  ASSERT_TRUE(actual.has_vertex_colors());
  ASSERT_TRUE(actual.has_vertex_texcoords2D());
  for (auto v : expected.vertices()) {
    Mesh::VertexHandle w(v.idx());
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(same_bits(expected.normal(v)[k], actual.normal(w)[k])) << v.idx();
    EXPECT_EQ(expected.color(v), actual.color(w)) << v.idx();
    EXPECT_EQ(expected.texcoord2D(v), actual.texcoord2D(w)) << v.idx();
  }
}

// Runs `read` and checks it throws fest::Error with Status::bad_input.
template <typename F>
void expect_bad_input(F read, const std::string& what) {
  try {
    read();
    ADD_FAILURE() << what << ": no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::bad_input) << what << ": " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": threw a non-fest exception: " << e.what();
  }
}

}  // namespace fest::test
