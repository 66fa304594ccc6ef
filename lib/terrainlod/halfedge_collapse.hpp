#pragma once
// A half-edge collapse on an OpenMesh triangle mesh with the very connectivity changes of
// OpenMesh's own `collapse` (the same half-edges, faces and vertices deleted, the same
// next/prev links, the same outgoing half-edge per vertex and half-edge per face), so
// that every later circulation -- and with it the collapse engine's order of work and its
// result -- is unchanged. Why not the library's: the Debian build of OpenMesh keeps its
// assertions, and each of its accessors (handle checks, status look-ups) is an out-of-line
// call there; the collapse cost about 6,400 instructions, a tenth of `simplify`. Here the
// kernel's inline accessors do the same work. Checked against the library in
// tests/unit/test_terrainlod_halfedge_collapse.cpp.

#include "core/mesh.hpp"

namespace fest::terrainlod {

// Collapses the from-vertex of `h` onto its to-vertex and removes the degenerate
// triangles (loops of two half-edges) this leaves, like TriMesh::collapse(h). The mesh
// needs vertex, edge and face status; the collapse must be allowed (CollapseCheck).
void collapse_halfedge(TriMesh& m, TriMesh::HalfedgeHandle h);

}  // namespace fest::terrainlod
