#pragma once
// Meshes for the tests of the engine's connectivity code: random grid meshes, and a
// handle-by-handle comparison of two meshes (the engine's own collapse and add_face must
// leave exactly the connectivity OpenMesh's would: same iteration order, hence the same
// simplified meshes). Both meshes need vertex, edge and face status.

#include <random>
#include <string>
#include <vector>

#include "core/mesh.hpp"

namespace fest::test {

// n x n vertices (vertex j n + i at (i, j)); cell by cell, row by row, split by its SW-NE
// diagonal where sw_ne() says so, else by the other.
template <typename Pick>
fest::TriMesh grid_mesh_with(int n, Pick sw_ne) {
  fest::TriMesh m;
  m.request_vertex_status();
  m.request_edge_status();
  m.request_face_status();
  std::vector<fest::TriMesh::VertexHandle> v;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) v.push_back(m.add_vertex(fest::TriMesh::Point(i, j, 0)));
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto a = v[j * n + i], b = v[j * n + i + 1], c = v[(j + 1) * n + i], d = v[(j + 1) * n + i + 1];
      if (sw_ne()) {
        m.add_face(a, b, d);
        m.add_face(a, d, c);
      } else {
        m.add_face(a, b, c);
        m.add_face(b, d, c);
      }
    }
  return m;
}

// Diagonals chosen at random (both directions occur in the engine's start meshes).
inline fest::TriMesh grid_mesh(int n, std::mt19937& rng) {
  return grid_mesh_with(n, [&rng] { return (rng() & 1) != 0; });
}

// Every cell split by its SW-NE diagonal.
inline fest::TriMesh ne_grid_mesh(int n) {
  return grid_mesh_with(n, [] { return true; });
}

// Every connectivity field and deleted flag of the two meshes; the first difference, or
// "" when there is none.
inline std::string first_difference(const fest::TriMesh& a, const fest::TriMesh& b) {
  if (a.n_halfedges() != b.n_halfedges() || a.n_vertices() != b.n_vertices() || a.n_faces() != b.n_faces())
    return "sizes";
  for (auto h : a.halfedges()) {
    const auto hb = fest::TriMesh::HalfedgeHandle(h.idx());
    if (a.next_halfedge_handle(h) != b.next_halfedge_handle(hb)) return "next of half-edge " + std::to_string(h.idx());
    if (a.prev_halfedge_handle(h) != b.prev_halfedge_handle(hb)) return "prev of half-edge " + std::to_string(h.idx());
    if (a.to_vertex_handle(h) != b.to_vertex_handle(hb)) return "to-vertex of half-edge " + std::to_string(h.idx());
    if (a.face_handle(h) != b.face_handle(hb)) return "face of half-edge " + std::to_string(h.idx());
  }
  for (auto e : a.edges())
    if (a.status(e).deleted() != b.status(fest::TriMesh::EdgeHandle(e.idx())).deleted())
      return "deleted flag of edge " + std::to_string(e.idx());
  for (auto v : a.all_vertices()) {
    const auto vb = fest::TriMesh::VertexHandle(v.idx());
    if (a.halfedge_handle(v) != b.halfedge_handle(vb)) return "half-edge of vertex " + std::to_string(v.idx());
    if (a.status(v).deleted() != b.status(vb).deleted()) return "deleted flag of vertex " + std::to_string(v.idx());
  }
  for (auto f : a.all_faces()) {
    const auto fb = fest::TriMesh::FaceHandle(f.idx());
    if (a.halfedge_handle(f) != b.halfedge_handle(fb)) return "half-edge of face " + std::to_string(f.idx());
    if (a.status(f).deleted() != b.status(fb).deleted()) return "deleted flag of face " + std::to_string(f.idx());
  }
  return "";
}

}  // namespace fest::test
