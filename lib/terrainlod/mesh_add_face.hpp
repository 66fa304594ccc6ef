#pragma once
// Adding a triangle to an OpenMesh triangle mesh with the very connectivity OpenMesh's own
// add_face makes (the same new edges in the same order, the same next/prev links, the same
// outgoing half-edge per vertex, the same half-edge per face, including the re-linking of
// boundary patches when the triangle joins two of them), so that the collapse engine built
// on it circulates in the same order as before and gives the same results. Why not the
// library's: the Debian OpenMesh keeps its assertions, and its accessors are out-of-line
// calls there (about 2,900 instructions per triangle: a tenth of `simplify`). Checked
// against the library in tests/unit/test_terrainlod_mesh_add_face.cpp.

#include "core/mesh.hpp"

namespace fest::terrainlod {

// Adds the triangle (a, b, c) like TriMesh::add_face(a, b, c): returns its handle, or an
// invalid handle (mesh unchanged) where the library refuses the face (a vertex that is not
// on the boundary, an edge that already has a face on this side, a patch that cannot be
// re-linked).
TriMesh::FaceHandle add_triangle(TriMesh& m, TriMesh::VertexHandle a, TriMesh::VertexHandle b,
                                 TriMesh::VertexHandle c);

}  // namespace fest::terrainlod
